#include "impasto/paintcore/brush_pose.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::paintcore {

BrushPlacement place_brush(const BrushPose& pose, int brush_cells, double spread) {
  const double tilt = std::min(std::hypot(pose.tilt_x_rad, pose.tilt_y_rad), kMaxTiltRad);
  double dir_x = 1.0, dir_y = 0.0;
  if (tilt > 0.0) {
    const double norm = std::hypot(pose.tilt_x_rad, pose.tilt_y_rad);
    dir_x = pose.tilt_x_rad / norm;
    dir_y = pose.tilt_y_rad / norm;
  }
  const double stretch = 1.0 / std::cos(tilt);
  const double shift = 0.25 * brush_cells * std::sin(tilt);
  BrushPlacement p;
  p.centre_x = pose.x_cells + shift * dir_x;
  p.centre_y = pose.y_cells + shift * dir_y;
  p.half_cells = 0.5 * brush_cells;
  // to_canvas = S * R(twist), S = I + (stretch - 1) d d^T.
  const double c = std::cos(pose.twist_rad), s = std::sin(pose.twist_rad);
  const double k = stretch - 1.0;
  const double s00 = 1 + k * dir_x * dir_x, s01 = k * dir_x * dir_y, s11 = 1 + k * dir_y * dir_y;
  p.to_canvas = {s00 * c + s01 * s, -s00 * s + s01 * c, s01 * c + s11 * s, -s01 * s + s11 * c};
  // to_brush = R(-twist) * S^-1, S^-1 = I + (1 / stretch - 1) d d^T.
  const double ki = 1.0 / stretch - 1.0;
  const double i00 = 1 + ki * dir_x * dir_x, i01 = ki * dir_x * dir_y, i11 = 1 + ki * dir_y * dir_y;
  p.to_brush = {c * i00 + s * i01, c * i01 + s * i11, -s * i00 + c * i01, -s * i01 + c * i11};
  if (spread != 1.0) {
    for (double& m : p.to_canvas) m *= spread;
    for (double& m : p.to_brush) m /= spread;
  }
  return p;
}

void validate(const PenSample& sample) {
  const auto check = [](double value, const char* field) {
    if (!std::isfinite(value))
      throw std::runtime_error(std::string("pen sample: field '") + field +
                               "' is not a finite number (" + std::to_string(value) + ")");
  };
  check(sample.time_s, "time_s");
  check(sample.x_mm, "x_mm");
  check(sample.y_mm, "y_mm");
  check(sample.pressure, "pressure");
  check(sample.tilt_x_deg, "tilt_x_deg");
  check(sample.tilt_y_deg, "tilt_y_deg");
  check(sample.rotation_deg, "rotation_deg");
}

BrushPose pose_from_sample(const PenSample& sample, double cell_mm, double max_depth_mm) {
  validate(sample);
  constexpr double deg = 3.14159265358979323846 / 180.0;
  BrushPose pose;
  // Positions absurdly far off the canvas are pulled in (still far off) so that no
  // arithmetic on them overflows.
  constexpr double kFarCells = 1e15;
  pose.x_cells = std::clamp(sample.x_mm / cell_mm, -kFarCells, kFarCells);
  pose.y_cells = std::clamp(sample.y_mm / cell_mm, -kFarCells, kFarCells);
  pose.depth_mm = std::clamp(static_cast<double>(sample.pressure), 0.0, 1.0) * max_depth_mm;
  pose.twist_rad = std::fmod(static_cast<double>(sample.rotation_deg), 360.0) * deg;
  pose.tilt_x_rad = std::clamp(static_cast<double>(sample.tilt_x_deg), -90.0, 90.0) * deg;
  pose.tilt_y_rad = std::clamp(static_cast<double>(sample.tilt_y_deg), -90.0, 90.0) * deg;
  return pose;
}

}  // namespace impasto::paintcore
