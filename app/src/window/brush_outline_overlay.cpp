#include "window/brush_outline_overlay.hpp"

#include <imgui.h>

namespace impasto::app::window {

void draw_brush_outline(const std::vector<Point2>& screen) {
  if (screen.size() < 3) return;
  std::vector<ImVec2> points;
  points.reserve(screen.size());
  for (const Point2& p : screen) {
    points.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
  }
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const int count = static_cast<int>(points.size());
  draw->AddPolyline(points.data(), count, IM_COL32(0, 0, 0, 200), ImDrawFlags_Closed, 3.0f);
  draw->AddPolyline(points.data(), count, IM_COL32(255, 255, 255, 230), ImDrawFlags_Closed, 1.2f);
}

void draw_pointer_note(float x, float y, const char* text) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 at(x + 18.0f, y + 18.0f);
  constexpr float kPad = 6.0f;
  draw->AddRectFilled(ImVec2(at.x - kPad, at.y - kPad),
                      ImVec2(at.x + size.x + kPad, at.y + size.y + kPad), IM_COL32(30, 30, 34, 235),
                      4.0f);
  draw->AddText(at, IM_COL32(255, 220, 120, 255), text);
}

}  // namespace impasto::app::window
