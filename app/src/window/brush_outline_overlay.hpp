#pragma once
// What the window draws at the pointer over the canvas, in ImGui's foreground list: the brush
// outline (brush_outline.hpp), a dark line under a light one so it shows on any paint, and a
// short note beside the pointer.
#include <vector>

#include "window/brush_outline.hpp"

namespace impasto::app::window {

void draw_brush_outline(const std::vector<Point2>& screen);
// `text` on a dark box just below and right of the pointer at (x, y).
void draw_pointer_note(float x, float y, const char* text);

}  // namespace impasto::app::window
