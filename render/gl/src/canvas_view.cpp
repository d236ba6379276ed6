#include "impasto/render_gl/canvas_view.hpp"

#include <algorithm>
#include <cmath>

namespace impasto::render_gl {

// Window (y down) → cell: subtract the viewport centre, rotate by −rotation, scale by
// 1 / zoom, add the view centre. The GL variant first flips y (GL's origin is bottom-left).
std::array<double, 2> CanvasView::window_to_cell(double x, double y_down, int viewport_w,
                                                 int viewport_h) const {
  const double dx = x - 0.5 * viewport_w;
  const double dy = y_down - 0.5 * viewport_h;
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  return {center_x_cells + (c * dx + s * dy) / pixels_per_cell,
          center_y_cells + (-s * dx + c * dy) / pixels_per_cell};
}

std::array<double, 2> CanvasView::cell_to_window(double cell_x, double cell_y, int viewport_w,
                                                 int viewport_h) const {
  const double u = (cell_x - center_x_cells) * pixels_per_cell;
  const double v = (cell_y - center_y_cells) * pixels_per_cell;
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  return {0.5 * viewport_w + c * u - s * v, 0.5 * viewport_h + s * u + c * v};
}

std::array<float, 9> CanvasView::screen_to_cell(int viewport_w, int viewport_h) const {
  // cell = A · (x, H − y_gl) + b, written as a matrix of (x, y_gl, 1).
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  const double k = 1.0 / pixels_per_cell;
  const double a00 = c * k, a01 = s * k, a10 = -s * k, a11 = c * k;
  const double cx = 0.5 * viewport_w, cy = 0.5 * viewport_h;
  // y_down = H − y_gl, so ∂/∂y_gl flips the second column, and the offset absorbs H.
  const double b0 = center_x_cells - a00 * cx - a01 * (cy - viewport_h);
  const double b1 = center_y_cells - a10 * cx - a11 * (cy - viewport_h);
  return {static_cast<float>(a00),  static_cast<float>(a10),  0.0f,
          static_cast<float>(-a01), static_cast<float>(-a11), 0.0f,
          static_cast<float>(b0),   static_cast<float>(b1),   1.0f};
}

CanvasView one_pixel_per_cell(int width_cells, int height_cells) {
  return {0.5 * width_cells, 0.5 * height_cells, 1.0, 0.0};
}

CanvasView fit_canvas(int width_cells, int height_cells, int viewport_w, int viewport_h) {
  const double zoom = 0.95 * std::min(static_cast<double>(viewport_w) / std::max(width_cells, 1),
                                      static_cast<double>(viewport_h) / std::max(height_cells, 1));
  return {0.5 * width_cells, 0.5 * height_cells, zoom > 0.0 ? zoom : 1.0, 0.0};
}

}  // namespace impasto::render_gl
