#pragma once
// Where the canvas sits in a viewport: pan, zoom and rotation, and the matrix the canvas
// shader uses to go from a window pixel to a canvas cell.
#include <array>

namespace impasto::render_gl {

struct CanvasView {
  double center_x_cells = 0.0;  // the canvas point shown at the viewport's centre
  double center_y_cells = 0.0;
  double pixels_per_cell = 1.0;  // zoom
  double rotation_rad = 0.0;     // the canvas turned counter-clockwise on screen

  // Column-major 3x3 (as glUniformMatrix3fv takes it) from GL window pixels (origin at the
  // bottom-left, y up) of a viewport_w x viewport_h viewport to canvas cells (y down).
  std::array<float, 9> screen_to_cell(int viewport_w, int viewport_h) const;
  // The same mapping for one point, and its inverse, for mouse input (window pixels with
  // y down, as GLFW reports the cursor).
  std::array<double, 2> window_to_cell(double x, double y_down, int viewport_w,
                                       int viewport_h) const;
  std::array<double, 2> cell_to_window(double cell_x, double cell_y, int viewport_w,
                                       int viewport_h) const;
};

// The view that shows every cell as exactly one pixel of a canvas-sized viewport.
CanvasView one_pixel_per_cell(int width_cells, int height_cells);

// The view that fits the whole canvas into the viewport with a margin.
CanvasView fit_canvas(int width_cells, int height_cells, int viewport_w, int viewport_h);

}  // namespace impasto::render_gl
