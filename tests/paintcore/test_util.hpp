#pragma once
// Helpers shared by the paintcore tests.
#include <cmath>
#include <string>
#include <vector>

#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore::test {

// A flat canvas (weave seed 0) of 0.1 mm cells unless told otherwise.
inline CanvasSpec flat_spec(int width = 128, int height = 128, double dpi = 254.0) {
  return CanvasSpec{width, height, dpi, 0};
}

inline BrushSettings round_brush(double size_mm = 2.0, double stiffness = 0.5) {
  BrushSettings s;
  s.head = "round";
  s.size_mm = size_mm;
  s.stiffness = stiffness;
  return s;
}

inline PenSample pen(double x_mm, double y_mm, float pressure, float tilt_x = 0.0f,
                     float tilt_y = 0.0f, float rotation = 0.0f) {
  PenSample s;
  s.x_mm = x_mm;
  s.y_mm = y_mm;
  s.pressure = pressure;
  s.tilt_x_deg = tilt_x;
  s.tilt_y_deg = tilt_y;
  s.rotation_deg = rotation;
  s.buttons = kPenTip;
  return s;
}

// One stroke of `samples` evenly spaced pen samples from (x0, y0) to (x1, y1), in mm.
inline void stroke_line(Painting& p, double x0, double y0, double x1, double y1, float pressure,
                        int samples = 20, float tilt_x = 0, float tilt_y = 0, float rotation = 0) {
  p.begin_stroke();
  for (int i = 0; i < samples; ++i) {
    const double t = samples > 1 ? static_cast<double>(i) / (samples - 1) : 0.0;
    p.stroke_to(pen(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, pressure, tilt_x, tilt_y, rotation));
  }
  p.end_stroke();
}

// Paint that should exist: loaded - wiped; and what does: canvas + brush.
inline PaintTotals expected_totals(const Painting& p) {
  PaintTotals t = p.loaded_totals();
  const PaintTotals w = p.wiped_totals();
  t.volume -= w.volume;
  for (std::size_t s = 0; s < t.pigment.size(); ++s) t.pigment[s] -= w.pigment[s];
  return t;
}

inline PaintTotals present_totals(const Painting& p) {
  PaintTotals t = p.canvas_totals();
  const PaintTotals b = p.brush_totals();
  t.volume += b.volume;
  for (std::size_t s = 0; s < t.pigment.size(); ++s) t.pigment[s] += b.pigment[s];
  return t;
}

inline double relative_error(double actual, double expected) {
  return std::abs(actual - expected) / std::max(std::abs(expected), 1e-300);
}

}  // namespace impasto::paintcore::test
