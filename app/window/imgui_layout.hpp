#pragma once
// Small ImGui helpers the window's parts share (one copy each).
#include <imgui.h>

#include <array>
#include <cfloat>
#include <functional>

namespace impasto::app::window {

// A display-RGB colour as ImGui's, opaque.
inline ImVec4 rgba(const std::array<float, 3>& rgb) {
  return ImVec4(rgb[0], rgb[1], rgb[2], 1.0f);
}

// The next item on this row when `width` more fits before `row_right`, else on a new row.
inline void flow(float width, float row_right) {
  const float x = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
  if (x + width < row_right) ImGui::SameLine();
}

// A dialog titled `title` in the middle of the window, 460 pixels wide and as tall as its
// fields (which may appear as it is filled in): `body` draws them and says whether `action`
// may be taken now; then the `action` and Cancel buttons. True in the frame `action` is
// pressed; `open` turns false then, on Cancel and by the close box.
inline bool action_dialog(const char* title, const char* action, bool& open,
                          const std::function<bool()>& body) {
  bool chosen = false;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(460, 0), ImVec2(460, FLT_MAX));
  if (ImGui::Begin(title, &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::BeginDisabled(!body());
    if (ImGui::Button(action)) chosen = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) open = false;
  }
  ImGui::End();
  if (chosen) open = false;
  return chosen;
}

}  // namespace impasto::app::window
