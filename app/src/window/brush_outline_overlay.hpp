#pragma once
// Draws the brush outline (brush_outline.hpp) over the canvas, in ImGui's foreground list: a
// dark line under a light one, so it shows on any paint.
#include <vector>

#include "window/brush_outline.hpp"

namespace impasto::app::window {

void draw_brush_outline(const std::vector<Point2>& screen);

}  // namespace impasto::app::window
