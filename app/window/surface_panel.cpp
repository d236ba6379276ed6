#include "window/surface_panel.hpp"

#include <imgui.h>
#include <impasto/render/subsurface.hpp>

#include <cstddef>

#include "window/enum_combo.hpp"

namespace impasto::app::window {

namespace surface = render::surface;

std::vector<std::string> varnish_names() {
  std::vector<std::string> names{"none"};
  for (const auto& entry : surface::kFinishNames) names.emplace_back(entry.name);
  return names;
}

int varnish_index(const std::optional<surface::Finish>& varnish) {
  if (!varnish) return 0;
  int index = 1;
  for (const auto& entry : surface::kFinishNames) {
    if (entry.value == *varnish) return index;
    ++index;
  }
  return 0;
}

std::optional<surface::Finish> varnish_at(int index) {
  int at = 1;
  for (const auto& entry : surface::kFinishNames) {
    if (at++ == index) return entry.value;
  }
  return std::nullopt;
}

void surface_panel(WindowState& s) {
  if (!ImGui::CollapsingHeader("Surface")) return;
  render::SurfaceSettings& surface = s.settings.surface;
  bool changed = enum_combo("model", surface.model, render::kSurfaceModelNames);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "As impasto render --surface:\n"
        "blinn: Blinn-Phong highlights on the K-M colour (fast, every paint shines alike);\n"
        "ghs: the rough oil or varnish surface per wavelength; the paint gets the light\n"
        "it lets through, and spreads it sideways in glazes and thick light paint.");
  }
  if (surface.model == render::SurfaceModel::ghs) {
    changed |= enum_combo("medium", surface.medium, surface::kFinishNames);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "The finish dried paint takes from its medium (paint mixed with a medium of its\n"
          "own keeps that); wet paint is always glossy.");
    }
    float amount = static_cast<float>(surface.medium_amount);
    if (ImGui::SliderFloat("medium amount", &amount, 0.0f, 1.0f, "%.2f")) {
      surface.medium_amount = amount;
    }
    changed |= ImGui::IsItemDeactivatedAfterEdit();  // new tables once, when let go
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("0: paint straight from the tube (dries satin); 1: the medium's finish");
    }
    const std::vector<std::string> names = varnish_names();
    const int current = varnish_index(surface.varnish);
    if (ImGui::BeginCombo("varnish", names[static_cast<std::size_t>(current)].c_str())) {
      for (std::size_t i = 0; i < names.size(); ++i) {
        const int index = static_cast<int>(i);
        if (ImGui::Selectable(names[i].c_str(), index == current) && index != current) {
          surface.varnish = varnish_at(index);
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "A dried varnish over the whole painting: its surface replaces the paint's");
    }
    changed |= ImGui::Checkbox("subsurface spread", &surface.subsurface);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "As impasto render without --no-subsurface: where a layer's light travels\n"
          "farther than a quarter of a cell inside it (glazes, thick light paint), it\n"
          "leaves the paint spread over its neighbours: a glaze softens the edge beneath.");
    }
    if (surface.subsurface) {
      ImGui::SameLine();
      // A view option: the cached view redraws (ShadedViewCache::look_of), the tables stay.
      ImGui::Checkbox("show where", &s.view_options.subsurface_map);
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "The map of the spread in place of the painting: each channel's spread length,\n"
            "%.0f cells to full brightness; elsewhere the painting, dimmed.",
            static_cast<double>(render::kSubsurfaceMapFullScaleCells));
      }
    }
  }
  if (changed) s.settings_changed = true;  // new surface tables, the canvas re-shaded
}

}  // namespace impasto::app::window
