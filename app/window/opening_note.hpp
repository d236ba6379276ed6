#pragma once
// The window's first frame: the panels, and where the canvas will be the background and a
// note, while the next frame shades the painting whole. Shaded coarsely instead and refined
// block by block over seconds, a painting first appeared blotchy, as if broken.
#include <array>

namespace impasto::app::window {

// Adds the note to ImGui's foreground list (between NewFrame and Render), centred in the
// canvas's part of a window_w × window_h window (left of the panels, panels_w wide).
void draw_opening_note(int window_w, int window_h, int panels_w);

// Clears the framebuffer to the view's background (display RGB), where the canvas will be.
void clear_to_background(const std::array<float, 3>& background_rgb, int fb_w, int fb_h);

}  // namespace impasto::app::window
