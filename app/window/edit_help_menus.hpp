#pragma once
// The Edit and Help menus, the Shortcuts and About windows, and the eyedropper's panel and
// cursor. Menu items show their keys from the one table (shortcuts.hpp) and ask for the same
// commands the keys do.
#include <cstddef>

#include "impasto/session/sim_worker.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// Inside the main menu bar (between BeginMainMenuBar and EndMainMenuBar).
void edit_menu(WindowState& state, session::SimWorker& worker, std::size_t undo_depth,
               std::size_t redo_depth);
void help_menu(WindowState& state);
// Help > Shortcuts and Help > About, when open.
void draw_help_windows(WindowState& state);

// The Eyedropper panel (in the side panel): the picked paint's colour, pigments and
// thickness, and loading it onto the brush.
void eyedropper_panel(WindowState& state, session::SimWorker& worker);
// The cursor while picking: a ring at the cursor showing the last picked colour.
void draw_pick_cursor(const WindowState& state, float x, float y);

}  // namespace impasto::app::window
