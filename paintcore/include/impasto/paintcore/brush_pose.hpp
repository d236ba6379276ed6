#pragma once
// Where the brush is and how it is held, in canvas cells, and how it maps onto the canvas.
#include <array>

#include "impasto/paintcore/pen_sample.hpp"

namespace impasto::paintcore {

inline constexpr double kMaxTiltRad = 1.0471975511965976;  // 60 degrees: tilt is clamped

struct BrushPose {
  double x_cells = 0;  // brush centre on the canvas; cell i spans [i, i + 1)
  double y_cells = 0;
  double depth_mm = 0;    // how far the tip sinks below the paint surface under the centre
  double twist_rad = 0;   // rotation of the head about the pen axis
  double tilt_x_rad = 0;  // pen tilt towards +x and +y
  double tilt_y_rad = 0;
};

// The affine map between brush cells and canvas cells for one pose: a tilted pen leans the
// head, so its footprint stretches along the tilt (by 1 / cos(tilt)) and shifts forward (by a
// quarter of the brush width times sin(tilt)); the twist rotates it.
struct BrushPlacement {
  double centre_x = 0, centre_y = 0;  // canvas cells, where brush-space (0, 0) lands
  std::array<double, 4> to_canvas{};  // 2x2 row-major: brush offset -> canvas offset
  std::array<double, 4> to_brush{};   // its inverse
  double half_cells = 0;              // half the brush grid width

  // Brush grid coordinates (continuous) of canvas point (x, y) in cells.
  void brush_coords(double x, double y, double& bx, double& by) const {
    const double dx = x - centre_x, dy = y - centre_y;
    bx = to_brush[0] * dx + to_brush[1] * dy + half_cells;
    by = to_brush[2] * dx + to_brush[3] * dy + half_cells;
  }
};

// `spread` (>= 1) widens the footprint about its centre: bristles splaying under pressure.
BrushPlacement place_brush(const BrushPose& pose, int brush_cells, double spread = 1.0);

// How a head with no twist of its own (a mouse, a tablet without barrel rotation) is turned:
// the heading (twist, radians) that trails the hand (Painting), and the brush outline the
// window draws at the pointer follows the same rule. After moving distance d along travel
// direction `travel_rad`, it turns by 1 - exp(-d / follow_length) of the way to the heading
// that puts the head's +v axis along the travel. Heads are symmetric under a half turn, so it
// turns the short way modulo pi (a brush drawn back does not flip over).
double follow_heading(double heading_rad, double travel_rad, double distance, double follow_length);
// The heading that puts the head's +v axis along the travel direction.
double heading_for_travel(double travel_rad);

// The pose for a pen sample: position mm -> cells, pressure (clamped to 0..1) times the
// brush's full depth, angles degrees -> radians. Throws std::runtime_error naming the field
// of a sample holding NaN or infinity.
BrushPose pose_from_sample(const PenSample& sample, double cell_mm, double max_depth_mm);
// Throws std::runtime_error naming the first non-finite field of the sample.
void validate(const PenSample& sample);

}  // namespace impasto::paintcore
