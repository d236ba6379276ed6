#include "window/paint_strip.hpp"

#include <imgui.h>
#include <impasto/data/pigments.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <string>

#include "impasto/data/lights.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/render/colour_recipe.hpp"
#include "window/imgui_layout.hpp"
#include "window/saved_mixes.hpp"

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

std::vector<std::string> pigment_names() {
  std::vector<std::string> names;
  for (const auto& pigment : data::PigmentDatabase::defaults().all()) names.push_back(pigment.name);
  return names;
}

}  // namespace

// The saved mixes, read on first use (what was passed over, said once), and their chips'
// colours: each mix's masstone under the window's light, as the colour target computes it.
void PaintStrip::update_saved(WindowState& s) {
  const std::vector<std::string> names = pigment_names();
  if (!mixes_) {
    SavedMixes loaded = load_saved_mixes(names);
    for (const auto& warning : loaded.warnings) s.notifications.warning(warning);
    mixes_ = std::move(loaded.mixes);
    light_.clear();
  }
  if (light_ == s.settings.light && rgb_.size() == mixes_->size()) return;
  const auto& pigments = data::PigmentDatabase::defaults().all();
  const render::RecipeFinder finder(pigments, data::light_from_spec(s.settings.light));
  rgb_.clear();
  for (const SavedMix& mix : *mixes_) {
    const std::vector<float> parts = mix_parts_of(mix, names);
    std::vector<render::RecipePart> recipe;
    for (std::size_t i = 0; i < parts.size(); ++i)
      if (parts[i] > 0.0f) recipe.push_back({i, parts[i]});
    const render::Recipe look = finder.evaluate(recipe, data::Lab{});
    rgb_.push_back({static_cast<float>(look.srgb[0]), static_cast<float>(look.srgb[1]),
                    static_cast<float>(look.srgb[2])});
  }
  light_ = s.settings.light;
}

void PaintStrip::store_saved(WindowState& s) {
  try {
    store_saved_mixes(*mixes_);
  } catch (const std::exception& e) {
    s.notifications.error(std::string("mixes not saved: ") + e.what());
  }
  light_.clear();  // the chips are made again
}

// The saved row: a chip each (click: load; right-click: remove), and "+" to save the
// Palette's mix under a name.
void PaintStrip::draw_saved(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                            float bar_right) {
  update_saved(s);
  const std::vector<std::string> names = pigment_names();
  flow(ImGui::CalcTextSize("saved").x + kChip, bar_right);
  ImGui::TextDisabled("saved");
  std::optional<std::size_t> remove;
  for (std::size_t i = 0; i < mixes_->size(); ++i) {
    const SavedMix& mix = (*mixes_)[i];
    flow(kChip, bar_right);
    ImGui::PushID(2000 + static_cast<int>(i));
    const bool clicked = ImGui::ColorButton("##saved", rgba(rgb_[i]), ImGuiColorEditFlags_NoTooltip,
                                            ImVec2(kChip, kChip));
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s\n%s\nclick: load the brush with it\nright-click: remove it",
                        files::terminal_text(mix.name).c_str(),
                        files::terminal_text(mix_description(mix)).c_str());
    }
    if (ImGui::BeginPopupContextItem("##saved_menu")) {
      if (ImGui::MenuItem(("Remove " + files::terminal_text(mix.name)).c_str())) remove = i;
      ImGui::EndPopup();
    }
    ImGui::PopID();
    if (clicked) {
      s.mix_parts = mix_parts_of(mix, names);
      s.mix_changed = true;
      load_palette_mix(s, worker, brush_volume_mm3);
    }
  }
  if (remove) {
    mixes_->erase(mixes_->begin() + static_cast<std::ptrdiff_t>(*remove));
    store_saved(s);
  }
  // "+": the Palette's mix, under a name (its parts, unless the painter types another).
  std::array<char, 128>& name = name_;
  flow(kChip, bar_right);
  const bool any =
      std::any_of(s.mix_parts.begin(), s.mix_parts.end(), [](float p) { return p > 0.0f; });
  ImGui::BeginDisabled(!any);
  if (ImGui::Button("+##save_mix", ImVec2(kChip, kChip))) {
    const std::string description = mix_description(saved_mix("", s.mix_parts, names));
    std::snprintf(name.data(), name.size(), "%s", description.c_str());
    ImGui::OpenPopup("Save mix");
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(any ? "save the Palette's mix among the saved ones"
                          : "save the Palette's mix (give pigments parts first)");
  if (ImGui::BeginPopup("Save mix")) {
    ImGui::SetNextItemWidth(260.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool entered =
        ImGui::InputText("name", name.data(), name.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    if ((ImGui::Button("Save") || entered) && name[0] != '\0') {
      SavedMix mix = saved_mix(name.data(), s.mix_parts, names);
      // The same name is the same mix: saved again, it takes the new parts.
      auto& mixes = *mixes_;
      std::erase_if(mixes, [&](const SavedMix& m) { return m.name == mix.name; });
      if (mixes.size() < kMaxSavedMixes) {
        mixes.push_back(std::move(mix));
        store_saved(s);
      } else {
        s.notifications.warning("at most " + std::to_string(kMaxSavedMixes) +
                                " saved mixes: remove one first (right-click it)");
      }
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

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

void PaintStrip::draw(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                      float bar_right) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  if (s.pigment_masstone_rgb.size() != pigments.size()) return;  // the chips are not made yet
  if (s.mix_parts.size() != pigments.size()) s.mix_parts.assign(pigments.size(), 0.0f);
  if (!palette_) {
    palette_ = load_strip_palette();
    for (const auto& warning : palette_->warnings) s.notifications.warning(warning);
  }
  // Chips close together: the library's paints fit one row of a 1000-pixel window's bar.
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(2.0f, ImGui::GetStyle().ItemSpacing.y));
  struct PopSpacing {
    ~PopSpacing() { ImGui::PopStyleVar(); }
  } pop_spacing;
  draw_paints(s, worker, brush_volume_mm3, bar_right);
  draw_recent_mixes(s, worker, brush_volume_mm3, bar_right);
  draw_saved(s, worker, brush_volume_mm3, bar_right);
  draw_palette_choice(s, bar_right);
}

void PaintStrip::draw_paints(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                             float bar_right) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  const bool adding = ImGui::GetIO().KeyShift || ImGui::GetIO().KeyCtrl;
  ImGui::TextDisabled("paints");
  std::optional<std::string> leave_out;
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    if (!palette_->shows(pigments[i].name)) continue;
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
          "in the Palette's mix (%.1f now)\nright-click: leave it out of the strip",
          pigments[i].name.c_str(), s.mix_parts[i]);
    }
    if (ImGui::BeginPopupContextItem("##paint_menu")) {
      if (ImGui::MenuItem(("Leave " + pigments[i].name + " out of the strip").c_str()))
        leave_out = pigments[i].name;
      ImGui::EndPopup();
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
  if (leave_out) {
    palette_->hidden.push_back(*leave_out);
    store_palette(s);
  }
}

// "...": every paint of the library with a box, ticked where the strip shows it.
void PaintStrip::draw_palette_choice(WindowState& s, float bar_right) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  flow(ImGui::CalcTextSize("...").x + 8.0f, bar_right);
  if (ImGui::SmallButton("...##palette")) ImGui::OpenPopup("Strip palette");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("choose the paints the strip shows");
  if (!ImGui::BeginPopup("Strip palette")) return;
  bool changed = false;
  for (const auto& pigment : pigments) {
    bool shown = palette_->shows(pigment.name);
    if (ImGui::Checkbox(pigment.name.c_str(), &shown)) {
      std::erase(palette_->hidden, pigment.name);
      if (!shown) palette_->hidden.push_back(pigment.name);
      changed = true;
    }
  }
  if (ImGui::Button("Show all")) {
    palette_->hidden.clear();
    changed = true;
  }
  ImGui::EndPopup();
  if (changed) store_palette(s);
}

void PaintStrip::store_palette(WindowState& s) {
  try {
    store_strip_palette(*palette_);
  } catch (const std::exception& e) {
    s.notifications.error(std::string("palette not saved: ") + e.what());
  }
}

void draw_recent_mixes(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                       float bar_right) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
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
