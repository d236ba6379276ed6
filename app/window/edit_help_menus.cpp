#include "window/edit_help_menus.hpp"

#include <imgui.h>

#include <string>

#include "about_text.hpp"
#include "impasto_version.hpp"
#include "window/eyedropper.hpp"
#include "window/shortcuts.hpp"
#include "window/tool_bar.hpp"

namespace impasto::app::window {
namespace {

// A menu item for `command`, its key text from the table.
void command_item(WindowState& s, Command command, bool selected = false, bool enabled = true) {
  const std::string keys = shortcut_text(command);
  if (ImGui::MenuItem(command_info(command).name, keys.empty() ? nullptr : keys.c_str(), selected,
                      enabled)) {
    s.commands.push_back(command);
  }
}

ImU32 to_u32(const std::array<float, 3>& rgb) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb[0], rgb[1], rgb[2], 1.0f));
}

}  // namespace

void edit_menu(WindowState& s, session::SimWorker& worker, std::size_t undo_depth,
               std::size_t redo_depth) {
  if (!ImGui::BeginMenu("Edit")) return;
  command_item(s, Command::kUndo, false, undo_depth > 0);
  command_item(s, Command::kRedo, false, redo_depth > 0);
  ImGui::Separator();
  command_item(s, Command::kBrush, !s.eyedropper.tool && s.brush.head != "knife");
  command_item(s, Command::kKnife, !s.eyedropper.tool && s.brush.head == "knife");
  command_item(s, Command::kEyedropper, s.eyedropper.tool);
  command_item(s, Command::kBrushSmaller);
  command_item(s, Command::kBrushLarger);
  ImGui::Separator();
  if (ImGui::BeginMenu("Brush presets", !s.presets.presets.empty())) {
    for (const BrushPreset& preset : s.presets.presets) {
      if (ImGui::MenuItem(preset.name.c_str())) {
        apply_preset(preset, s, worker);
        break;
      }
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Save brush as preset...")) s.open_save_preset = true;
  bool any_user = false;
  for (const BrushPreset& preset : s.presets.presets) any_user = any_user || preset.user;
  if (ImGui::BeginMenu("Delete my preset", any_user)) {
    for (const BrushPreset& preset : s.presets.presets) {
      if (preset.user && ImGui::MenuItem(preset.name.c_str())) {
        delete_user_preset(s, BrushPreset(preset));
        break;
      }
    }
    ImGui::EndMenu();
  }
  ImGui::EndMenu();
}

void help_menu(WindowState& s) {
  if (!ImGui::BeginMenu("Help")) return;
  command_item(s, Command::kShowShortcuts, s.show_shortcuts);
  if (ImGui::MenuItem("About Impasto")) s.show_about = true;
  ImGui::EndMenu();
}

void draw_help_windows(WindowState& s) {
  const ImGuiIO& io = ImGui::GetIO();
  // Escape closes them, as it closes the dialogs (a popup over them takes it first).
  if ((s.show_shortcuts || s.show_about) && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) &&
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    s.show_shortcuts = s.show_about = false;
  }
  if (s.show_shortcuts) {
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(1.0f);  // a table to read, not the painting through it
    if (ImGui::Begin("Shortcuts", &s.show_shortcuts,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_NoCollapse)) {
      if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        std::string group;
        for (const CommandInfo& info : commands()) {
          const std::string keys = all_shortcut_texts(info.command);
          if (keys.empty()) continue;
          if (group != info.group) {
            group = info.group;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", info.group);
          }
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(keys.c_str());
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(info.name);
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextDisabled("Mouse");
        for (const GestureHelp& gesture : mouse_gestures()) {
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(gesture.gesture);
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(gesture.what);
        }
        ImGui::EndTable();
      }
    }
    ImGui::End();
  }
  if (s.show_about) {
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("About Impasto", &s.show_about,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_NoCollapse)) {
      ImGui::Text("Impasto %s", IMPASTO_VERSION);
      ImGui::TextUnformatted(
          "2.5D thick paint: a fluid on a height field that the brush\n"
          "pushes, picks up and deposits, coloured from measured pigment\n"
          "spectra through the Kubelka-Munk model.");
      ImGui::TextUnformatted(kLicenceText);
      ImGui::TextDisabled("impasto --help lists the commands; docs/ in the sources.");
    }
    ImGui::End();
  }
}

void eyedropper_panel(WindowState& s, session::SimWorker& worker) {
  EyedropperState& e = s.eyedropper;
  if (e.reveal) ImGui::SetNextItemOpen(true);  // a pick opens the panel that shows it
  e.reveal = false;
  if (!ImGui::CollapsingHeader("Eyedropper")) return;
  if (!e.picked) {
    ImGui::TextWrapped("%s (%s), or Alt + click while painting: picks the paint under the cursor.",
                       command_info(Command::kEyedropper).name,
                       shortcut_text(Command::kEyedropper).c_str());
  } else {
    const PickedPaint& p = *e.picked;
    const float size = 2.0f * ImGui::GetFrameHeight();
    ImGui::ColorButton("##picked_masstone",
                       ImVec4(p.masstone_rgb[0], p.masstone_rgb[1], p.masstone_rgb[2], 1),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(size, size));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("masstone: the picked mix, opaque");
    ImGui::SameLine(0.0f, 1.0f);
    ImGui::ColorButton("##picked_layer", ImVec4(p.layer_rgb[0], p.layer_rgb[1], p.layer_rgb[2], 1),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(size, size));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("as picked: a layer as thick as the paint there, over the ground");
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::Text("%s paint at cell %.0f, %.0f", p.dry ? "dry" : "wet", p.cell[0], p.cell[1]);
    ImGui::Text("wet %.2f mm, dry %.2f mm", p.wet_mm, p.dry_mm);
    ImGui::Text("medium %s", picked_medium_text(p).c_str());
    ImGui::EndGroup();
    for (const auto& part : p.mix) {
      if (part.parts >= 0.05) {
        ImGui::BulletText("%5.1f %%  %s", part.parts, part.pigment.c_str());
      } else {
        ImGui::BulletText(" < 0.1 %%  %s", part.pigment.c_str());  // a trace, smeared in
      }
    }
    if (ImGui::Button("Load onto brush")) {
      load_onto_brush(worker, picked_load(p, s.load_volume_mm3, s.paint_body));
      s.notifications.info("brush loaded with the picked paint");
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("wipe the brush and load %.0f mm³ of this mix (%s body)", s.load_volume_mm3,
                        s.paint_body.c_str());
    ImGui::SameLine();
  }
  ImGui::Checkbox("load on pick", &e.load_on_pick);
  if (!e.message.empty()) ImGui::TextWrapped("%s", e.message.c_str());
}

void draw_pick_cursor(const WindowState& s, float x, float y) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 c(x, y);
  constexpr float kRing = 16.0f;
  if (s.eyedropper.picked && s.eyedropper.picked->rendered) {
    // The ring's band is the picked paint's colour, as ArtRage and Krita show it.
    draw->AddCircle(c, kRing, to_u32(s.eyedropper.picked->layer_rgb), 32, 7.0f);
  }
  draw->AddCircle(c, kRing + 4.0f, IM_COL32(0, 0, 0, 220), 32, 1.5f);
  draw->AddCircle(c, kRing - 4.0f, IM_COL32(255, 255, 255, 220), 32, 1.5f);
  draw->AddLine(ImVec2(x - 5, y), ImVec2(x + 5, y), IM_COL32(0, 0, 0, 255), 1.0f);
  draw->AddLine(ImVec2(x, y - 5), ImVec2(x, y + 5), IM_COL32(0, 0, 0, 255), 1.0f);
}

}  // namespace impasto::app::window
