#pragma once
// The brush on the canvas: the outline of the head's footprint at the pointer, as the next
// stroke would set it down — its size, the head's shape, turned as the head turns to the
// travel (paintcore::follow_heading) and splayed by the pressure the pointer paints with.
// Geometry only (no GL, no ImGui): the window draws it over the canvas, never into the
// painting, and hides it while a panel or a dialog has the pointer.
#include <impasto/paintcore/brush_head.hpp>
#include <impasto/paintcore/brush_pose.hpp>
#include <impasto/paintcore/pen_sample.hpp>
#include <impasto/render_gl/canvas_view.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace impasto::app {

using Point2 = std::array<double, 2>;

// The head's outline in brush space (u across, v along the travel, both in [-1, 1]): for each
// of `rays` directions from the centre, where the footprint ends (found by bisection; every
// head is star-shaped about its centre). Empty when the centre itself is not covered.
std::vector<Point2> head_outline(const paintcore::BrushHead& head, int rays = 96);

// The outline set down by `placement` (paintcore::place_brush), in canvas cells.
std::vector<Point2> outline_in_cells(const std::vector<Point2>& outline_uv,
                                     const paintcore::BrushPlacement& placement);

// Follows the pointer and keeps the outline of one head, rebuilt only when the head changes.
class BrushOutline {
 public:
  // The pointer over the canvas at (x, y) cells: the heading trails its travel, as a stroke's
  // head would, over a length of one brush width (`brush_cells`).
  void pointer_at(double x_cells, double y_cells, int brush_cells);
  // A tablet's pen at `sample` (canvas mm), hovering or pressed: its tilt leans the outline as
  // it leans the head (paintcore::place_brush), a barrel rotation turns it; a pen without one
  // trails its travel as the pointer does.
  void pen_at(const paintcore::PenSample& sample, double cell_mm, int brush_cells);
  // The outline in window pixels (y down) for the head, its grid width in cells, the pressure
  // that splays it and the view; the polygon is closed by its first point.
  std::vector<Point2> on_screen(const paintcore::BrushHead& head, int brush_cells, double pressure,
                                const render_gl::CanvasView& view, int viewport_w, int viewport_h);
  double heading_rad() const { return heading_rad_; }

 private:
  double x_cells_ = 0.0, y_cells_ = 0.0;
  bool seen_ = false;
  double heading_rad_ = 0.0;
  double tilt_x_rad_ = 0.0, tilt_y_rad_ = 0.0;  // a pen's (the mouse has none)
  std::optional<double> twist_rad_;             // a pen's barrel rotation, when it has one
  std::string head_key_;                        // the head whose outline is kept
  std::vector<Point2> outline_uv_;
};

}  // namespace impasto::app
