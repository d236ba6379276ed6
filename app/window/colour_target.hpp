#pragma once
// The colour target (a panel under the Palette board): the painter picks a colour (a picker, or
// typed as hex or RGB) and Impasto proposes the pigments of the library whose masstone comes
// nearest it under the window's light (render/colour_recipe.hpp): the best of one, two and three,
// each with its CIEDE2000 and a chip of how it looks; Load makes that the mix and loads the brush.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "impasto/render/colour_recipe.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// The Palette's parts for a recipe: its shares as parts of ten (the parts sliders' range),
// to a tenth, over `pigment_count` pigments of the library; every pigment of the recipe keeps
// at least a tenth.
std::vector<float> recipe_mix_parts(const render::Recipe& recipe, std::size_t pigment_count);

// The target and its recipes: a panel under the Palette board, which owns them.
class ColourTarget {
 public:
  // A colour picked elsewhere (the reference image): its recipes under `light` are found at
  // once and the panel opens at its next draw.
  void pick(const std::array<float, 3>& rgb, const std::string& light);
  // Draws the panel (collapsed until opened) in the current ImGui window: the recipes follow
  // the target and the window's light (state.settings.light); Load sets state.mix_parts and
  // loads the brush (load_palette_mix).
  void draw(WindowState& s, session::SimWorker& worker, double brush_volume_mm3);

  const std::array<float, 3>& target() const { return target_; }
  const std::vector<render::Recipe>& recipes() const { return recipes_; }
  const std::string& recipes_light() const { return recipes_light_; }

 private:
  void find(const std::string& light);

  std::array<float, 3> target_{0.54f, 0.23f, 0.17f};  // display sRGB
  std::vector<render::Recipe> recipes_;
  std::string recipes_light_;  // the light they were found under
  bool open_next_ = false;
};

}  // namespace impasto::app::window
