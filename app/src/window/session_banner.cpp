#include "window/session_banner.hpp"

#include <imgui.h>

namespace impasto::app::window {
namespace {

void banner(const char* id, float y, const ImVec4& colour, const std::string& text) {
  const ImGuiIO& io = ImGui::GetIO();
  const float width = io.DisplaySize.x * 0.6f;
  ImGui::SetNextWindowPos(ImVec2((io.DisplaySize.x - width) * 0.5f, y));
  ImGui::SetNextWindowSize(ImVec2(width, 0));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, colour);
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PushTextWrapPos(width - 10.0f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace

void draw_session_banners(const SimStats& stats, const std::string& notice) {
  float y = ImGui::GetFrameHeight() + 4.0f;  // below the menu bar
  const ImVec4 red(0.6f, 0.05f, 0.05f, 0.95f);
  if (!stats.recording_error.empty()) {
    banner("##recording", y, red, stats.recording_error);
    y += ImGui::GetTextLineHeightWithSpacing() * 3.0f;
  }
  if (!stats.autosave_error.empty()) {
    banner("##autosave", y, red, stats.autosave_error);
    y += ImGui::GetTextLineHeightWithSpacing() * 3.0f;
  }
  if (!notice.empty()) banner("##notice", y, ImVec4(0.45f, 0.35f, 0.05f, 0.95f), notice);
}

RecoveryChoice draw_recovery_offer(const std::vector<SessionEntry>& sessions,
                                   std::optional<std::size_t> previewing) {
  RecoveryChoice choice;
  if (sessions.empty()) return choice;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Recover unsaved work", nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted("Impasto did not end cleanly last time. These sessions can be rebuilt");
  ImGui::TextUnformatted("from their autosave and recording:");
  for (std::size_t i = 0; i < sessions.size(); ++i) {
    const SessionEntry& s = sessions[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::Separator();
    ImGui::TextUnformatted(s.painting ? s.painting->string().c_str() : "an untitled painting");
    ImGui::TextDisabled("%s", s.id.c_str());
    if (previewing == i) {
      ImGui::TextColored(ImVec4(0.9f, 0.8f, 0.3f, 1.0f), "previewed below");
    } else if (ImGui::Button("Preview")) {
      choice = {RecoveryChoice::kPreview, i};
    }
    ImGui::SameLine();
    if (ImGui::Button("Recover")) choice = {RecoveryChoice::kRecover, i};
    ImGui::SameLine();
    if (ImGui::Button("Discard")) choice = {RecoveryChoice::kDiscard, i};
    ImGui::PopID();
  }
  ImGui::Separator();
  if (ImGui::Button("Later")) choice = {RecoveryChoice::kLater, 0};
  ImGui::SameLine();
  ImGui::TextDisabled("(impasto recover --list shows them too)");
  ImGui::End();
  return choice;
}

}  // namespace impasto::app::window
