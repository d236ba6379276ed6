#include "window/paint_strip.hpp"

#include <imgui.h>
#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <string>

#include "window/imgui_layout.hpp"

namespace impasto::app::window {
namespace {

constexpr float kChip = 18.0f;

// How the mix looks: a single paint's masstone, else the Palette's masstone chip.
std::array<float, 3> mix_rgb(const WindowState& s) {
  int only = -1, count = 0;
  for (std::size_t i = 0; i < s.mix_parts.size(); ++i) {
    if (s.mix_parts[i] > 0.0f) {
      only = static_cast<int>(i);
      ++count;
    }
  }
  if (count == 1 && static_cast<std::size_t>(only) < s.pigment_masstone_rgb.size())
    return s.pigment_masstone_rgb[static_cast<std::size_t>(only)];
  return s.swatch_masstone_rgb;
}

}  // namespace

void remember_mix(std::vector<RecentMix>& recent, const RecentMix& mix) {
  recent.erase(std::remove_if(recent.begin(), recent.end(),
                              [&](const RecentMix& r) { return r.parts == mix.parts; }),
               recent.end());
  recent.insert(recent.begin(), mix);
  if (recent.size() > kRecentMixes) recent.resize(kRecentMixes);
}

void load_palette_mix(WindowState& s, session::SimWorker& worker, double brush_volume_mm3) {
  const input::LoadEvent load = load_event(s);
  if (load.mix.empty()) return;
  // Both go to the session, so a replay loads the same way.
  const bool dirty = brush_volume_mm3 > 0.0 || worker.stats().queued > 0;
  if (s.wipe_before_load && dirty) worker.submit(input::WipeEvent{});
  worker.submit(load);
  remember_mix(s.recent_mixes, {s.mix_parts, mix_rgb(s)});
}

void draw_paint_strip(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                      float bar_right) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  if (s.pigment_masstone_rgb.size() != pigments.size()) return;  // the chips are not made yet
  if (s.mix_parts.size() != pigments.size()) s.mix_parts.assign(pigments.size(), 0.0f);
  const bool adding = ImGui::GetIO().KeyShift || ImGui::GetIO().KeyCtrl;
  // Chips close together: the library's paints fit one row of a 1000-pixel window's bar.
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(2.0f, ImGui::GetStyle().ItemSpacing.y));
  struct PopSpacing {
    ~PopSpacing() { ImGui::PopStyleVar(); }
  } pop_spacing;
  ImGui::TextDisabled("paints");
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    flow(kChip, bar_right);
    ImGui::PushID(static_cast<int>(i));
    const bool clicked = ImGui::ColorButton("##paint", rgba(s.pigment_masstone_rgb[i]),
                                            ImGuiColorEditFlags_NoTooltip, ImVec2(kChip, kChip));
    // The lower half: a thin glaze over the ground, where a dark paint shows its hue (the
    // masstones of the blues, the violet, the green and the black are all near-black).
    if (i < s.pigment_glaze_rgb.size()) {
      const ImVec2 top = ImGui::GetItemRectMin(), bottom = ImGui::GetItemRectMax();
      ImGui::GetWindowDrawList()->AddRectFilled(
          ImVec2(top.x, 0.5f * (top.y + bottom.y)), bottom,
          ImGui::ColorConvertFloat4ToU32(rgba(s.pigment_glaze_rgb[i])));
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "%s\nclick: load the brush with it\nShift- or Ctrl-click: a part more "
          "in the Palette's mix (%.1f now)",
          pigments[i].name.c_str(), s.mix_parts[i]);
    }
    ImGui::PopID();
    if (!clicked) continue;
    if (adding) {
      s.mix_parts[i] += 1.0f;
    } else {
      std::fill(s.mix_parts.begin(), s.mix_parts.end(), 0.0f);
      s.mix_parts[i] = 1.0f;
      load_palette_mix(s, worker, brush_volume_mm3);
    }
    s.mix_changed = true;
  }
  if (s.recent_mixes.empty()) return;
  flow(ImGui::CalcTextSize("recent").x + kChip, bar_right);
  ImGui::TextDisabled("recent");
  for (std::size_t i = 0; i < s.recent_mixes.size(); ++i) {
    flow(kChip, bar_right);
    ImGui::PushID(1000 + static_cast<int>(i));
    const RecentMix mix = s.recent_mixes[i];  // (a click reorders the list)
    const bool clicked = ImGui::ColorButton("##recent", rgba(mix.rgb),
                                            ImGuiColorEditFlags_NoTooltip, ImVec2(kChip, kChip));
    if (ImGui::IsItemHovered()) {
      std::string parts;
      for (std::size_t p = 0; p < mix.parts.size() && p < pigments.size(); ++p) {
        if (mix.parts[p] <= 0.0f) continue;
        char part[96];
        std::snprintf(part, sizeof part, "%s%g %s", parts.empty() ? "" : " + ",
                      static_cast<double>(mix.parts[p]), pigments[p].name.c_str());
        parts += part;
      }
      ImGui::SetTooltip("%s\nclick: load the brush with this mix again", parts.c_str());
    }
    ImGui::PopID();
    if (clicked && mix.parts.size() == s.mix_parts.size()) {
      s.mix_parts = mix.parts;
      s.mix_changed = true;
      load_palette_mix(s, worker, brush_volume_mm3);
      break;  // the list changed
    }
  }
}

}  // namespace impasto::app::window
