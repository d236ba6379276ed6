#include "window/opening_note.hpp"

#include <imgui.h>
#include <impasto/render_gl/gl.hpp>

namespace impasto::app::window {

void draw_opening_note(int window_w, int window_h, int panels_w) {
  const char* text = "Shading the painting...";
  const ImVec2 size = ImGui::CalcTextSize(text);
  const float x = 0.5f * static_cast<float>(window_w - panels_w) - 0.5f * size.x;
  const float y = 0.5f * static_cast<float>(window_h) - 0.5f * size.y;
  ImGui::GetForegroundDrawList()->AddText(ImVec2(x, y), IM_COL32(235, 235, 235, 255), text);
}

void clear_to_background(const std::array<float, 3>& background_rgb, int fb_w, int fb_h) {
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(background_rgb[0], background_rgb[1], background_rgb[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace impasto::app::window
