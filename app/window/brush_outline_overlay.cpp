#include "window/brush_outline_overlay.hpp"

#include <imgui.h>

#include "window/panels.hpp"

namespace impasto::app::window {

namespace {
constexpr double kPointerNote_s = 5.0;  // how long the note beside the pointer stays
}  // namespace

void PointerOverlay::stroke_began(double on_brush_mm3, double now_s) {
  if (told_empty_brush_ || on_brush_mm3 > 0.0) return;
  told_empty_brush_ = true;
  empty_brush_note_until_s_ = now_s + kPointerNote_s;
}

void PointerOverlay::draw(const PaintingSnapshot& painting, double pressure,
                          const render_gl::CanvasView& view, int window_w, int window_h, double x,
                          double y, double now_s, const paintcore::PenSample* pen) {
  if (pen && painting.dpi > 0.0) {
    const double cell_mm = 25.4 / painting.dpi;
    const auto at =
        view.cell_to_window(pen->x_mm / cell_mm, pen->y_mm / cell_mm, window_w, window_h);
    x = at[0];
    y = at[1];
    pressure = pen->tip_down() ? pen->pressure : 0.0;
  }
  const bool in_window = x >= 0.0 && y >= 0.0 && x < window_w && y < window_h;
  if (!in_window || !on_canvas_ || painting.brush_cells < 1) return;
  if (pen && painting.dpi > 0.0) {
    outline_.pen_at(*pen, 25.4 / painting.dpi, painting.brush_cells);
  } else {
    const auto cell = view.window_to_cell(x, y, window_w, window_h);
    outline_.pointer_at(cell[0], cell[1], painting.brush_cells);
  }
  if (now_s < empty_brush_note_until_s_) {
    draw_pointer_note(static_cast<float>(x), static_cast<float>(y),
                      "The brush is empty: choose paint in the Palette, then Load brush");
  }
  draw_brush_outline(outline_.on_screen(painting.brush_head, painting.brush_cells, pressure, view,
                                        window_w, window_h));
}

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
