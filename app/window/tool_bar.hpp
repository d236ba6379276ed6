#pragma once
// The bar over the canvas's top left: the tools (brush, palette knife, eyedropper) and the
// brush presets (click one to paint with it; save the brush as a preset; right-click one of
// your own to delete it). Its buttons ask for the same commands as the keys (shortcuts.hpp).
#include <string>

#include "impasto/session/sim_worker.hpp"
#include "window/brush_presets.hpp"
#include "window/paint_strip.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// The window's brush as a preset named `name`, and back: apply_preset sets the brush, the
// body, the load and the pressure, and sends the brush to the painting.
BrushPreset preset_from_state(const WindowState& state, const std::string& name);
void apply_preset(const BrushPreset& preset, WindowState& state, session::SimWorker& worker);
// Saves the brush as the user's preset `name` (replacing one of that name) and reloads the
// library; says what happened in state.message.
void save_user_preset(WindowState& state, const std::string& name);
void delete_user_preset(WindowState& state, const BrushPreset& preset);
// Reads the shipped and the user's presets into state.presets.
void reload_presets(WindowState& state);

void draw_tool_bar(WindowState& state, session::SimWorker& worker, double brush_volume_mm3,
                   PaintStrip& strip);

}  // namespace impasto::app::window
