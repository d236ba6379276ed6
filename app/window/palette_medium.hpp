#pragma once
// The Palette panel's medium: what the paint loaded onto the brush is mixed with (none, or
// gloss, satin or matte medium, and how much), by the names of a stroke file's `medium=`
// (docs/surface.md, "Medium and varnish in the painting"). Every load the window makes
// carries it (load_event, the palette board's pick-up), so the session records it.
#include "window/window_state.hpp"

namespace impasto::app::window {

// Draws the choice on the current line: the finish ("none" first) and, with a medium, its
// amount. Returns whether either changed.
bool medium_choice(WindowState& state);

}  // namespace impasto::app::window
