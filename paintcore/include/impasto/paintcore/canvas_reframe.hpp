#pragma once
// Changing the canvas's size: growing it around an anchor (new cells are clean canvas) or
// cropping it to a rectangle. Both are one operation, a frame: the new size and where the
// old canvas's top-left cell lands in it. Paint inside the new frame is copied cell for cell
// (bit-exact); paint outside it is cut away and reported. The weave moves with the paint
// (CanvasSpec::weave_origin_*), so the cloth under a kept cell is the cloth it had.
#include <string>

#include "impasto/paintcore/canvas.hpp"

namespace impasto::paintcore {

struct CanvasFrame {
  int width_cells = 0;
  int height_cells = 0;
  int offset_x_cells = 0;  // old cell (x, y) becomes new cell (x + offset_x, y + offset_y)
  int offset_y_cells = 0;
};

// Where the old canvas sits when the size changes: a corner, an edge's middle or the centre.
enum class CanvasAnchor {
  kTopLeft,
  kTop,
  kTopRight,
  kLeft,
  kCenter,
  kRight,
  kBottomLeft,
  kBottom,
  kBottomRight
};

// "top-left", "top", "top-right", "left", "center" (or "centre"), "right", "bottom-left",
// "bottom", "bottom-right"; throws naming the choices otherwise.
CanvasAnchor parse_canvas_anchor(const std::string& name);
const char* canvas_anchor_name(CanvasAnchor anchor);

// A new size with the old canvas placed at the anchor (a smaller size crops around it).
CanvasFrame anchored_frame(int old_width, int old_height, int width, int height,
                           CanvasAnchor anchor);
// The rectangle x, y, width, height of the old canvas (cells) becomes the whole canvas.
CanvasFrame crop_frame(int x, int y, int width, int height);

// Throws std::runtime_error naming the field when the frame gives no usable canvas (a size
// outside 1..kMaxCanvasCells, or no overlap with the old canvas: that would keep nothing).
void validate(const CanvasFrame& frame, const CanvasSpec& old_spec);

// The spec of the reframed canvas: the new size, the weave origin moved by the offset.
CanvasSpec reframed_spec(const CanvasSpec& spec, const CanvasFrame& frame);

// The paint a reframe cuts away, per cell in mm of paint summed over the cut cells (wet and
// every dry layer); multiply by the cell area for mm^3.
struct CutPaint {
  double volume_mm = 0;
  std::vector<double> pigment_mm;  // by slot
};

// The canvas in the new frame: wet tiles, dry layers and cracks moved cell for cell; `cut`
// receives what fell outside. The frame must be valid (validate).
Canvas reframed_canvas(const Canvas& canvas, const CanvasFrame& frame, int slot_count,
                       CutPaint& cut);

}  // namespace impasto::paintcore
