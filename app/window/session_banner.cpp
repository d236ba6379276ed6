#include "window/session_banner.hpp"

#include <imgui.h>
#include <impasto/render_gl/gl.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "impasto/session/preview.hpp"

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

void draw_session_banners(const session::SimStats& stats, const std::string& notice) {
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

RecoveryChoice draw_recovery_offer(const std::vector<session::SessionEntry>& sessions,
                                   const std::optional<RecoveryPreview>& preview) {
  RecoveryChoice choice;
  constexpr const char* kTitle = "Recover unsaved work";
  if (sessions.empty()) return choice;
  if (!ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return choice;
  ImGui::TextUnformatted("Impasto did not end cleanly last time. These sessions can be rebuilt");
  ImGui::TextUnformatted("from their autosave and recording:");
  for (std::size_t i = 0; i < sessions.size(); ++i) {
    const session::SessionEntry& s = sessions[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::Separator();
    ImGui::TextUnformatted(s.painting ? s.painting->string().c_str() : "an untitled painting");
    ImGui::TextDisabled("%s", s.id.c_str());
    if (preview && preview->index == i) {
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
  if (preview && preview->texture) {
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(preview->texture)),
                 ImVec2(static_cast<float>(preview->width), static_cast<float>(preview->height)));
    ImGui::TextDisabled("rebuilt from %s", preview->caption.c_str());
  }
  // The last choice that empties the list closes the offer.
  const bool last =
      choice.kind == RecoveryChoice::kLater ||
      ((choice.kind == RecoveryChoice::kRecover || choice.kind == RecoveryChoice::kDiscard) &&
       sessions.size() == 1);
  if (last) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return choice;
}

PreviewTexture::~PreviewTexture() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void PreviewTexture::show(const paintcore::Painting& painting) {
  const render::Image full = session::render_preview(painting);
  const int step = std::max(1, (std::max(full.width, full.height) + 479) / 480);
  width_ = std::max(1, full.width / step);
  height_ = std::max(1, full.height / step);
  std::vector<float> rgb;
  rgb.reserve(static_cast<std::size_t>(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const float* p = full.pixel(x * step, y * step);
      rgb.insert(rgb.end(), p, p + 3);
    }
  }
  if (!texture_) glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width_, height_, 0, GL_RGB, GL_FLOAT, rgb.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace impasto::app::window
