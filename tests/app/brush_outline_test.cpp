// The brush outline the window draws at the pointer: the head's footprint boundary, placed as
// the engine places the head (size, heading, splay), checked against the head's own shape.
#include "window/brush_outline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impasto::app {
namespace {

// Where a ray from the centre at `angle` leaves the outline: the outline point nearest it.
double reach_along(const std::vector<Point2>& outline, double angle) {
  double best = 0.0, closest = 1e9;
  for (const Point2& p : outline) {
    const double a = std::atan2(p[1], p[0]);
    const double off = std::abs(std::remainder(a - angle, 2.0 * std::numbers::pi));
    if (off < closest) {
      closest = off;
      best = std::hypot(p[0], p[1]);
    }
  }
  return best;
}

TEST(BrushOutline, TheRoundHeadIsACircleOnTheFootprintsEdge) {
  const paintcore::BrushHead round = paintcore::load_named_brush_head("round");
  const std::vector<Point2> outline = head_outline(round, 64);
  ASSERT_EQ(outline.size(), 64u);
  double low = 1e9, high = 0.0;
  for (const Point2& p : outline) {
    const double r = std::hypot(p[0], p[1]);
    low = std::min(low, r);
    high = std::max(high, r);
    // On the edge: covered just inside, not just outside.
    EXPECT_TRUE(round.covers(0.99 * p[0], 0.99 * p[1]));
    EXPECT_FALSE(round.covers(1.01 * p[0] + 1e-3, 1.01 * p[1] + 1e-3));
  }
  EXPECT_LT(high - low, 0.05) << "a round head is round";
  EXPECT_GT(low, 0.8);
}

TEST(BrushOutline, AFlatIsWideAcrossAndThinAlongTheTravel) {
  const paintcore::BrushHead flat = paintcore::load_named_brush_head("flat");
  const std::vector<Point2> outline = head_outline(flat);
  // u is across the head (its width), v along the travel (its thickness).
  EXPECT_GT(reach_along(outline, 0.0), 2.0 * reach_along(outline, 0.5 * std::numbers::pi));
}

TEST(BrushOutline, PlacedItTurnsAndScalesAsTheEngineSetsTheHead) {
  const std::vector<Point2> square = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  paintcore::BrushPose pose;
  pose.x_cells = 50.0;
  pose.y_cells = 20.0;
  pose.twist_rad = 0.5 * std::numbers::pi;  // a quarter turn: u along +y
  const auto placed = outline_in_cells(square, paintcore::place_brush(pose, 40, 1.5));
  // Half the grid (20 cells) splayed 1.5 times: 30 cells from the centre.
  EXPECT_NEAR(placed[0][0], 50.0, 1e-9);
  EXPECT_NEAR(placed[0][1], 50.0, 1e-9);
  EXPECT_NEAR(placed[1][0], 20.0, 1e-9);
  EXPECT_NEAR(placed[1][1], 20.0, 1e-9);
}

TEST(BrushOutline, ItTrailsThePointersTravelAsAStrokesHeadDoes) {
  BrushOutline outline;
  outline.pointer_at(0.0, 0.0, 10);
  for (int i = 1; i <= 100; ++i) outline.pointer_at(0.0, 1.0 * i, 10);  // down the rows
  // +v along the travel: the heading that points it down +y is 0.
  EXPECT_NEAR(std::remainder(outline.heading_rad(), std::numbers::pi), 0.0, 1e-3);
  for (int i = 1; i <= 100; ++i) outline.pointer_at(1.0 * i, 100.0, 10);  // then along +x
  EXPECT_NEAR(std::remainder(outline.heading_rad() + 0.5 * std::numbers::pi, std::numbers::pi), 0.0,
              1e-3);
}

// Width and height of an outline's bounding box.
std::array<double, 2> extent(const std::vector<Point2>& outline) {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Point2& p : outline) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  return {x1 - x0, y1 - y0};
}

// A tablet's pen, hovering: its tilt leans the outline as it leans the head (stretched along
// the tilt by 1 / cos), its barrel rotation turns a flat; the mouse at the same spot has none.
TEST(BrushOutline, APensTiltLeansItAndItsRotationTurnsIt) {
  const paintcore::BrushHead round = paintcore::load_named_brush_head("round");
  const render_gl::CanvasView view = render_gl::one_pixel_per_cell(200, 200);
  paintcore::PenSample pen;
  pen.x_mm = 10.0, pen.y_mm = 10.0;  // cell (100, 100) at 0.1 mm a cell
  pen.tilt_x_deg = 45.0f;
  pen.buttons = paintcore::kPenInRange;
  BrushOutline tilted, mouse;
  tilted.pen_at(pen, 0.1, 40);
  mouse.pointer_at(100.0, 100.0, 40);
  const auto leaned = extent(tilted.on_screen(round, 40, 0.0, view, 200, 200));
  const auto upright = extent(mouse.on_screen(round, 40, 0.0, view, 200, 200));
  EXPECT_NEAR(leaned[0] / upright[0], std::sqrt(2.0), 0.05) << "stretched along x by 1/cos 45°";
  EXPECT_NEAR(leaned[1] / upright[1], 1.0, 0.02);
  // The mouse's outline after the pen's has no tilt left.
  tilted.pointer_at(100.0, 100.0, 40);
  EXPECT_NEAR(extent(tilted.on_screen(round, 40, 0.0, view, 200, 200))[0], upright[0], 1e-6);

  const paintcore::BrushHead flat = paintcore::load_named_brush_head("flat");
  pen.tilt_x_deg = 0.0f;
  BrushOutline turned;
  pen.rotation_deg = 90.0f;
  turned.pen_at(pen, 0.1, 40);
  const auto quarter = extent(turned.on_screen(flat, 40, 0.0, view, 200, 200));
  pen.rotation_deg = 180.0f;
  turned.pen_at(pen, 0.1, 40);
  const auto half = extent(turned.on_screen(flat, 40, 0.0, view, 200, 200));
  EXPECT_GT(quarter[1], 2.0 * quarter[0]) << "a quarter turn puts the flat's width along y";
  EXPECT_GT(half[0], 2.0 * half[1]);
}

}  // namespace
}  // namespace impasto::app
