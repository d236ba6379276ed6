#pragma once
// The colour target (a panel under the Palette board): the painter picks a colour (a picker, or
// typed as hex or RGB) and Impasto proposes the pigments of the library whose masstone comes
// nearest it under the window's light (render/colour_recipe.hpp): the best of one, two and three,
// each with its CIEDE2000 and a chip of how it looks; Load makes that the mix and loads the brush.
#include <cstddef>
#include <vector>

#include "impasto/render/colour_recipe.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// The Palette's parts for a recipe: its shares as parts of ten (the parts sliders' range),
// to a tenth, over `pigment_count` pigments of the library; every pigment of the recipe keeps
// at least a tenth.
std::vector<float> recipe_mix_parts(const render::Recipe& recipe, std::size_t pigment_count);

// The recipes for state.colour_target under state.settings.light, found anew.
void find_recipes(WindowState& s);

// Draws the panel (collapsed until opened; under the Palette board) in the current ImGui
// window.
void colour_target_panel(WindowState& s, session::SimWorker& worker, double brush_volume_mm3);

}  // namespace impasto::app::window
