#include "window/palette_medium.hpp"

#include <imgui.h>

#include <string>
#include <vector>

#include "window/surface_panel.hpp"

namespace impasto::app::window {

bool medium_choice(WindowState& s) {
  bool changed = false;
  // "none", then each finish: the Surface panel's varnish list is the same choice.
  const std::vector<std::string> names = varnish_names();
  const int current = varnish_index(s.paint_medium);
  const std::string shown = "medium: " + names[static_cast<std::size_t>(current)];
  ImGui::SetNextItemWidth(118.0f);
  if (ImGui::BeginCombo("##paint_medium", shown.c_str())) {
    for (int index = 0; index < static_cast<int>(names.size()); ++index) {
      if (ImGui::Selectable(names[static_cast<std::size_t>(index)].c_str(), index == current) &&
          index != current) {
        s.paint_medium = varnish_at(index);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "The medium the loaded paint is mixed with: its dried surface is that finish's\n"
        "(none: the Surface panel's medium decides)");
  if (s.paint_medium) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(42.0f);
    changed |=
        ImGui::SliderFloat("##paint_medium_amount", &s.paint_medium_amount, 0.0f, 1.0f, "%.2f");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "The amount of medium: 0 tube paint (dries satin), 1 the medium's own finish");
  }
  return changed;
}

}  // namespace impasto::app::window
