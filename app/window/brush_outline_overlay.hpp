#pragma once
// What the window draws at the pointer over the canvas, in ImGui's foreground list: the brush
// outline (brush_outline.hpp), a dark line under a light one so it shows on any paint, and a
// short note beside the pointer.
#include <vector>

#include "window/brush_outline.hpp"

namespace impasto::app::window {

struct PaintingSnapshot;

// What the window shows at the pointer: the brush's outline while the pointer is over the
// canvas, and once a session, when a stroke begins with nothing on the brush, a note saying so.
class PointerOverlay {
 public:
  // Decided between frames (a panel, menu or dialog at the pointer hides the outline): ImGui's
  // own windows cover the canvas in the middle of a frame.
  void set_on_canvas(bool on_canvas) { on_canvas_ = on_canvas; }
  // A stroke begins with `on_brush_mm3` on the brush: an empty one is told, once.
  void stroke_began(double on_brush_mm3, double now_s);
  // Draws at window pixel (x, y) with the pointer's pressure; or, where a tablet's pen is near
  // (`pen`: its newest sample, canvas mm), where the pen is, leaned by its tilt and splayed by
  // its pressure (none while it hovers).
  void draw(const PaintingSnapshot& painting, double pressure, const render_gl::CanvasView& view,
            int window_w, int window_h, double x, double y, double now_s,
            const paintcore::PenSample* pen = nullptr);

 private:
  BrushOutline outline_;
  bool on_canvas_ = false;
  bool told_empty_brush_ = false;
  double empty_brush_note_until_s_ = 0.0;
};

void draw_brush_outline(const std::vector<Point2>& screen);
// `text` on a dark box just below and right of the pointer at (x, y).
void draw_pointer_note(float x, float y, const char* text);

}  // namespace impasto::app::window
