#include "window/colour_target.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "window/imgui_layout.hpp"
#include "window/paint_strip.hpp"

namespace impasto::app::window {

std::vector<float> recipe_mix_parts(const render::Recipe& recipe, std::size_t pigment_count) {
  std::vector<float> parts(pigment_count, 0.0f);
  for (const render::RecipePart& part : recipe.parts) {
    if (part.pigment >= pigment_count) continue;
    parts[part.pigment] = std::max(0.1f, static_cast<float>(std::round(100.0 * part.share) / 10.0));
  }
  return parts;
}

void ColourTarget::find(const std::string& light) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  const render::RecipeFinder finder(pigments, data::light_from_spec(light));
  recipes_ = finder.find(render::srgb_to_lab({target_[0], target_[1], target_[2]}));
  recipes_light_ = light;
}

void ColourTarget::pick(const std::array<float, 3>& rgb, const std::string& light) {
  target_ = rgb;
  find(light);
  open_next_ = true;
}

void ColourTarget::draw(WindowState& s, session::SimWorker& worker, double brush_volume_mm3) {
  if (std::exchange(open_next_, false)) ImGui::SetNextItemOpen(true);
  if (!ImGui::CollapsingHeader("Colour target")) return;
  ImGui::SetNextItemWidth(150.0f);
  const bool picked = ImGui::ColorEdit3("target", target_.data(), ImGuiColorEditFlags_DisplayHex);
  ImGui::SameLine();
  // Found again when the colour or the light changes (a few tens of milliseconds).
  if (ImGui::Button("Find") || picked || (!recipes_.empty() && recipes_light_ != s.settings.light))
    find(s.settings.light);
  const auto& pigments = data::PigmentDatabase::defaults().all();
  for (std::size_t r = 0; r < recipes_.size(); ++r) {
    const render::Recipe& recipe = recipes_[r];
    ImGui::PushID(static_cast<int>(r));
    const std::array<float, 3> rgb{static_cast<float>(recipe.srgb[0]),
                                   static_cast<float>(recipe.srgb[1]),
                                   static_cast<float>(recipe.srgb[2])};
    ImGui::ColorButton("##recipe", rgba(rgb), ImGuiColorEditFlags_NoTooltip,
                       ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
    ImGui::SameLine();
    if (ImGui::Button("Load")) {
      s.mix_parts = recipe_mix_parts(recipe, pigments.size());
      s.mix_changed = true;
      load_palette_mix(s, worker, brush_volume_mm3);
    }
    ImGui::SameLine();
    std::string text;
    for (const render::RecipePart& part : recipe.parts) {
      char share[16];
      std::snprintf(share, sizeof share, "%s%.0f%% ", text.empty() ? "" : "+ ", 100.0 * part.share);
      text += share + pigments[part.pigment].name + " ";
    }
    ImGui::Text("dE00 %.1f", recipe.delta_e00);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("CIEDE2000 of its masstone from the target, under the light");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopID();
  }
  if (recipes_.empty()) {
    ImGui::BeginDisabled();
    ImGui::TextWrapped(
        "Pick or type a colour: the library's pigments nearest it, under this light.");
    ImGui::EndDisabled();
  }
}

}  // namespace impasto::app::window
