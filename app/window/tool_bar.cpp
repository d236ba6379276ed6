#include "window/tool_bar.hpp"

#include "window/imgui_layout.hpp"
#include "window/paint_strip.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>

#include "window/shortcuts.hpp"

namespace impasto::app::window {
namespace {

constexpr const char* kSavePresetPopup = "Save brush preset";

// A tool button, lit while its tool is the one in use; `tip` says what it is and its key.
void tool_button(WindowState& s, const char* label, Command command, bool active) {
  if (active)
    ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  if (ImGui::Button(label)) s.commands.push_back(command);
  if (active) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s (%s)", command_info(command).name, shortcut_text(command).c_str());
}

bool is_current(const BrushPreset& p, const WindowState& s) {
  return p.head == s.brush.head && p.size_mm == s.brush.size_mm &&
         p.stiffness == s.brush.stiffness && p.body == s.paint_body &&
         p.load_mm3 == static_cast<double>(s.load_volume_mm3);
}

}  // namespace

BrushPreset preset_from_state(const WindowState& s, const std::string& name) {
  BrushPreset preset;
  preset.name = name;
  preset.head = s.brush.head;
  preset.size_mm = s.brush.size_mm;
  preset.stiffness = s.brush.stiffness;
  preset.body = s.paint_body;
  preset.load_mm3 = s.load_volume_mm3;
  preset.pressure = s.mouse_pressure;
  preset.pressure_from_speed = s.pressure_from_speed;
  return preset;
}

void apply_preset(const BrushPreset& preset, WindowState& s, session::SimWorker& worker) {
  s.brush.head = preset.head;
  s.brush.size_mm = preset.size_mm;
  s.brush.stiffness = preset.stiffness;
  s.paint_body = preset.body;
  s.load_volume_mm3 = static_cast<float>(preset.load_mm3);
  s.mouse_pressure = preset.pressure;
  s.pressure_from_speed = preset.pressure_from_speed;
  s.eyedropper.tool = false;
  worker.submit(brush_event(s));
  s.notifications.info("brush: " + preset.name);
}

void reload_presets(WindowState& s) {
  std::filesystem::path shipped;
  try {
    shipped = shipped_presets_dir();
  } catch (const std::exception& e) {
    s.notifications.warning(e.what());  // no data folder: only the user's presets
  }
  s.presets = load_brush_presets(shipped, user_presets_dir(), s.brush_heads);
}

void save_user_preset(WindowState& s, const std::string& name) {
  const std::filesystem::path folder = user_presets_dir();
  if (folder.empty()) {
    s.notifications.error("cannot save a preset: neither XDG_CONFIG_HOME nor HOME is set");
    return;
  }
  try {
    const BrushPreset preset = preset_from_state(s, name);
    const std::filesystem::path file = folder / preset_file_name(name);
    write_brush_preset(preset, file);
    reload_presets(s);
    s.notifications.info("saved preset " + file.string());
  } catch (const std::exception& e) {
    s.notifications.error(e.what());
  }
}

void delete_user_preset(WindowState& s, const BrushPreset& preset) {
  if (!preset.user) return;
  std::error_code error;
  std::filesystem::remove(preset.file, error);
  if (error) {
    s.notifications.error("cannot delete " + preset.file.string() + ": " + error.message());
  } else {
    s.notifications.info("deleted preset " + preset.name);
  }
  reload_presets(s);
}

void draw_tool_bar(WindowState& s, session::SimWorker& worker, double brush_volume_mm3,
                   PaintStrip& strip) {
  const ImGuiIO& io = ImGui::GetIO();
  constexpr float kPanelsWidth = 330.0f;  // the side panel (panels.cpp) on the right
  const float width = std::max(200.0f, io.DisplaySize.x - kPanelsWidth - 16.0f);
  ImGui::SetNextWindowPos(ImVec2(8.0f, ImGui::GetFrameHeight() + 6.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, io.DisplaySize.y / 3));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##tools", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  const float right = ImGui::GetWindowPos().x + width - ImGui::GetStyle().WindowPadding.x;
  const bool knife = s.brush.head == "knife";
  tool_button(s, "Brush", Command::kBrush, !s.eyedropper.tool && !knife);
  ImGui::SameLine();
  tool_button(s, "Knife", Command::kKnife, !s.eyedropper.tool && knife);
  ImGui::SameLine();
  tool_button(s, "Eyedropper", Command::kEyedropper, s.eyedropper.tool);
  ImGui::SameLine();
  ImGui::TextDisabled("|");
  for (std::size_t i = 0; i < s.presets.presets.size(); ++i) {
    const BrushPreset& preset = s.presets.presets[i];
    const float button =
        ImGui::CalcTextSize(preset.name.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
    flow(button, right);
    ImGui::PushID(static_cast<int>(i));
    const bool current = is_current(preset, s);
    if (current)
      ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    const bool clicked = ImGui::Button(preset.name.c_str());
    if (current) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s, %.1f mm, stiffness %.2f, %s body, %.0f mm³%s", preset.head.c_str(),
                        preset.size_mm, preset.stiffness, preset.body.c_str(), preset.load_mm3,
                        preset.user ? "\n(yours: right-click to delete)" : "");
    }
    if (preset.user && ImGui::BeginPopupContextItem("##preset_menu")) {
      if (ImGui::MenuItem("Delete preset")) {
        const BrushPreset doomed = preset;  // the library is reloaded below
        ImGui::EndPopup();
        ImGui::PopID();
        delete_user_preset(s, doomed);
        break;
      }
      ImGui::EndPopup();
    }
    ImGui::PopID();
    if (clicked) {
      apply_preset(s.presets.presets[i], s, worker);
      break;
    }
  }
  flow(ImGui::CalcTextSize("+ Save preset").x + 2 * ImGui::GetStyle().FramePadding.x, right);
  if (ImGui::Button("+ Save preset")) s.open_save_preset = true;
  if (s.open_save_preset) {
    s.open_save_preset = false;
    s.preset_name_input.clear();
    ImGui::OpenPopup(kSavePresetPopup);
  }
  if (ImGui::BeginPopupModal(kSavePresetPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s, %.1f mm, stiffness %.2f, %s body, %.0f mm³", s.brush.head.c_str(),
                s.brush.size_mm, s.brush.stiffness, s.paint_body.c_str(), s.load_volume_mm3);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(260.0f);
    const bool entered =
        ImGui::InputText("name", &s.preset_name_input, ImGuiInputTextFlags_EnterReturnsTrue);
    if ((ImGui::Button("Save") || entered) && !s.preset_name_input.empty()) {
      save_user_preset(s, s.preset_name_input);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  for (const std::string& error : s.presets.errors)
    ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", error.c_str());
  strip.draw(s, worker, brush_volume_mm3, right);
  ImGui::End();
}

}  // namespace impasto::app::window
