// CanvasView: window pixels <-> canvas cells under pan, zoom and rotation, and the GL
// matrix the canvas shader uses (no GL context needed).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "impasto/render_gl/canvas_view.hpp"

namespace impasto::render_gl {
namespace {

TEST(CanvasView, WindowToCellAndBackIsTheIdentity) {
  const CanvasView view{123.4, 56.7, 2.5, 0.7};
  for (double x : {0.0, 17.0, 640.5, 1279.0}) {
    for (double y : {0.0, 33.0, 799.0}) {
      const auto cell = view.window_to_cell(x, y, 1280, 800);
      const auto back = view.cell_to_window(cell[0], cell[1], 1280, 800);
      EXPECT_NEAR(back[0], x, 1e-9);
      EXPECT_NEAR(back[1], y, 1e-9);
    }
  }
}

TEST(CanvasView, ZoomAndRotationActAboutTheViewportCentre) {
  const CanvasView view{100.0, 50.0, 4.0, std::numbers::pi / 2};
  // The centre shows the view centre.
  auto c = view.window_to_cell(400, 300, 800, 600);
  EXPECT_NEAR(c[0], 100.0, 1e-12);
  EXPECT_NEAR(c[1], 50.0, 1e-12);
  // A quarter turn: the canvas's +x points down the (y-down) window, so the cell one to the
  // right of the centre lands 4 px (the zoom) below the window's centre.
  auto w = view.cell_to_window(101.0, 50.0, 800, 600);
  EXPECT_NEAR(w[0], 400.0, 1e-9);
  EXPECT_NEAR(w[1], 304.0, 1e-9);
}

TEST(CanvasView, ShaderMatrixMatchesWindowToCellWithGlRowsFlipped) {
  const CanvasView view{321.0, 77.0, 0.8, -0.4};
  const int w = 640, h = 480;
  const auto m = view.screen_to_cell(w, h);  // column-major
  for (double x : {0.5, 100.5, 639.5}) {
    for (double y_gl : {0.5, 240.5, 479.5}) {
      const double cx = m[0] * x + m[3] * y_gl + m[6];
      const double cy = m[1] * x + m[4] * y_gl + m[7];
      const auto expected = view.window_to_cell(x, h - y_gl, w, h);
      EXPECT_NEAR(cx, expected[0], 1e-3);
      EXPECT_NEAR(cy, expected[1], 1e-3);
    }
  }
}

TEST(CanvasView, OnePixelPerCellMapsPixelCentresToCellCentres) {
  const CanvasView view = one_pixel_per_cell(150, 100);
  const auto m = view.screen_to_cell(150, 100);
  // GL pixel (x, row r from the bottom) shows cell (x, 99 - r).
  const double cx = m[0] * 10.5 + m[3] * 0.5 + m[6];
  const double cy = m[1] * 10.5 + m[4] * 0.5 + m[7];
  EXPECT_DOUBLE_EQ(std::floor(cx), 10.0);
  EXPECT_DOUBLE_EQ(std::floor(cy), 99.0);
}

TEST(CanvasView, FitShowsTheWholeCanvas) {
  const CanvasView view = fit_canvas(4000, 1000, 800, 600);
  const auto top_left = view.cell_to_window(0, 0, 800, 600);
  const auto bottom_right = view.cell_to_window(4000, 1000, 800, 600);
  EXPECT_GE(top_left[0], 0.0);
  EXPECT_GE(top_left[1], 0.0);
  EXPECT_LE(bottom_right[0], 800.0);
  EXPECT_LE(bottom_right[1], 600.0);
  EXPECT_GT(bottom_right[0] - top_left[0], 700.0);  // and uses most of the width
}

}  // namespace
}  // namespace impasto::render_gl
