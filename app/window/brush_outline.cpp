#include "window/brush_outline.hpp"

#include <cmath>
#include <exception>
#include <numbers>

namespace impasto::app {

std::vector<Point2> head_outline(const paintcore::BrushHead& head, int rays) {
  std::vector<Point2> outline;
  if (!head.covers(0.0, 0.0) || rays < 3) return outline;
  // The unit square's corners lie at sqrt(2): no head reaches further.
  constexpr double kReach = std::numbers::sqrt2;
  constexpr int kBisections = 24;
  outline.reserve(static_cast<std::size_t>(rays));
  for (int k = 0; k < rays; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / rays;
    const double du = std::cos(angle), dv = std::sin(angle);
    double inside = 0.0, outside = kReach;
    if (head.covers(kReach * du, kReach * dv)) {
      inside = kReach;
    } else {
      for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (inside + outside);
        (head.covers(mid * du, mid * dv) ? inside : outside) = mid;
      }
    }
    outline.push_back({inside * du, inside * dv});
  }
  return outline;
}

std::vector<Point2> outline_in_cells(const std::vector<Point2>& outline_uv,
                                     const paintcore::BrushPlacement& placement) {
  std::vector<Point2> cells;
  cells.reserve(outline_uv.size());
  const auto& m = placement.to_canvas;
  for (const Point2& uv : outline_uv) {
    // Brush grid offset from the centre: u across the grid's columns, v down its rows.
    const double bx = uv[0] * placement.half_cells, by = uv[1] * placement.half_cells;
    cells.push_back(
        {placement.centre_x + m[0] * bx + m[1] * by, placement.centre_y + m[2] * bx + m[3] * by});
  }
  return cells;
}

void BrushOutline::pen_at(const paintcore::PenSample& sample, double cell_mm, int brush_cells) {
  paintcore::BrushPose pose;
  try {
    pose = paintcore::pose_from_sample(sample, cell_mm, 0.0);
  } catch (const std::exception&) {
    return;  // a sample the engine would refuse (NaN tilt): the outline stays where it was
  }
  pointer_at(pose.x_cells, pose.y_cells, brush_cells);
  tilt_x_rad_ = pose.tilt_x_rad;
  tilt_y_rad_ = pose.tilt_y_rad;
  // As the engine turns a head (Painting::stroke_to): by the pen's rotation when it reports one.
  twist_rad_.reset();
  if (sample.rotation_deg != 0.0f) twist_rad_ = pose.twist_rad;
}

void BrushOutline::pointer_at(double x_cells, double y_cells, int brush_cells) {
  tilt_x_rad_ = tilt_y_rad_ = 0.0;
  twist_rad_.reset();
  if (!seen_) {
    x_cells_ = x_cells;
    y_cells_ = y_cells;
    seen_ = true;
    return;
  }
  const double dx = x_cells - x_cells_, dy = y_cells - y_cells_;
  const double moved = std::hypot(dx, dy);
  if (moved <= 0.0) return;
  heading_rad_ = paintcore::follow_heading(heading_rad_, std::atan2(dy, dx), moved,
                                           std::max(1.0, 1.0 * brush_cells));
  x_cells_ = x_cells;
  y_cells_ = y_cells;
}

std::vector<Point2> BrushOutline::on_screen(const paintcore::BrushHead& head, int brush_cells,
                                            double pressure, const render_gl::CanvasView& view,
                                            int viewport_w, int viewport_h) {
  if (!seen_ || brush_cells < 1) return {};
  if (head.name != head_key_ || outline_uv_.empty()) {
    outline_uv_ = head_outline(head);
    head_key_ = head.name;
  }
  paintcore::BrushPose pose;
  pose.x_cells = x_cells_;
  pose.y_cells = y_cells_;
  pose.twist_rad = twist_rad_.value_or(heading_rad_);
  pose.tilt_x_rad = tilt_x_rad_;
  pose.tilt_y_rad = tilt_y_rad_;
  const paintcore::BrushPlacement placement =
      paintcore::place_brush(pose, brush_cells, 1.0 + head.splay * pressure);
  std::vector<Point2> screen;
  for (const Point2& cell : outline_in_cells(outline_uv_, placement)) {
    const auto at = view.cell_to_window(cell[0], cell[1], viewport_w, viewport_h);
    screen.push_back({at[0], at[1]});
  }
  return screen;
}

}  // namespace impasto::app
