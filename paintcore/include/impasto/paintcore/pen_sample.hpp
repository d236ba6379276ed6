#pragma once
#include <cstdint>

namespace impasto::paintcore {

// Pen buttons and states, as bits of PenSample::buttons.
enum PenButton : std::uint32_t {
  kPenTip = 1u << 0,      // the tip touches the surface
  kPenBarrel1 = 1u << 1,  // first barrel (side) button
  kPenBarrel2 = 1u << 2,  // second barrel button
  kPenEraser = 1u << 3,   // the pen is inverted / eraser end in use
  kPenInRange = 1u << 4,  // the pen is near enough to be tracked
};

// One sample of a pen (tablet, mouse or recorded stroke), in canvas units.
// Positions are millimetres on the canvas, angles are degrees as in files and UI.
struct PenSample {
  double time_s = 0.0;        // seconds since the start of the session
  double x_mm = 0.0;          // canvas position, +x to the right
  double y_mm = 0.0;          // canvas position, +y downwards (image rows)
  float pressure = 0.0f;      // 0 (hover) .. 1 (full)
  float tilt_x_deg = 0.0f;    // tilt of the pen towards +x, -90..90
  float tilt_y_deg = 0.0f;    // tilt of the pen towards +y, -90..90
  float rotation_deg = 0.0f;  // barrel rotation (twist), 0..360
  std::uint32_t buttons = 0;  // PenButton bits

  bool tip_down() const { return (buttons & kPenTip) != 0; }
};

}  // namespace impasto::paintcore
