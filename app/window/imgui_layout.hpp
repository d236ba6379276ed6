#pragma once
// Small ImGui helpers the window's parts share (one copy each).
#include <imgui.h>

#include <array>

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

}  // namespace impasto::app::window
