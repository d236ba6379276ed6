#include "window/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot_ticks.hpp"

namespace impasto::app::window {

double series_at(const PlotSeries& s, double x) {
  if (s.x.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (x <= s.x.front()) return s.y.front();
  if (x >= s.x.back()) return s.y.back();
  const auto it = std::upper_bound(s.x.begin(), s.x.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - s.x.begin());
  const double t = (x - s.x[i - 1]) / (s.x[i] - s.x[i - 1]);
  return s.y[i - 1] + t * (s.y[i] - s.y[i - 1]);
}

double draw_plot(const PlotOptions& o, std::span<const PlotSeries> series) {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = o.y_min_from_data ? HUGE_VAL : o.y_min, y1 = -HUGE_VAL;
  for (const auto& s : series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (std::isfinite(o.y_max)) y1 = o.y_max;
  if (!(x1 > x0)) x0 = 380, x1 = 730;
  if (!(y1 > y0)) y1 = y0 + 1;
  if (!std::isfinite(o.y_max)) y1 += 0.05 * (y1 - y0);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(o.id, o.size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float font = ImGui::GetFontSize();
  const float left = origin.x + 40, right = origin.x + o.size.x - 6;
  const float top = origin.y + (o.title.empty() ? 4 : font + 4),
              bottom = origin.y + o.size.y - font - 4;
  auto px = [&](double x) {
    return static_cast<float>(left + (x - x0) / (x1 - x0) * (right - left));
  };
  auto py = [&](double y) {
    return static_cast<float>(bottom - (y - y0) / (y1 - y0) * (bottom - top));
  };
  const ImU32 frame = IM_COL32(150, 150, 160, 255), grid = IM_COL32(70, 70, 80, 255),
              text = IM_COL32(200, 200, 205, 255);

  draw->AddRectFilled(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(25, 25, 30, 255));
  if (!o.title.empty()) draw->AddText(ImVec2(left, origin.y), text, o.title.c_str());
  for (double t : nice_ticks(x0, x1, 5)) {
    draw->AddLine(ImVec2(px(t), top), ImVec2(px(t), bottom), grid);
    const std::string label = tick_label(t);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText(ImVec2(px(t) - w / 2, bottom + 2), text, label.c_str());
  }
  if (!o.x_label.empty()) {
    const float w = ImGui::CalcTextSize(o.x_label.c_str()).x;
    draw->AddText(ImVec2(right - w, bottom + 2), text, o.x_label.c_str());
  }
  for (double t : nice_ticks(y0, y1, 4)) {
    draw->AddLine(ImVec2(left, py(t)), ImVec2(right, py(t)), grid);
    const std::string label = tick_label(t);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText(ImVec2(left - w - 3, py(t) - font / 2), text, label.c_str());
  }
  for (double m : o.markers_x) {
    if (m >= x0 && m <= x1)
      draw->AddLine(ImVec2(px(m), top), ImVec2(px(m), bottom), IM_COL32(255, 200, 60, 160), 1.5f);
  }
  draw->PushClipRect(ImVec2(left, top), ImVec2(right, bottom), true);
  for (const auto& s : series) {
    std::vector<ImVec2> points;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i])) points.emplace_back(px(s.x[i]), py(std::min(s.y[i], y1 * 10)));
    if (s.dashed) {
      for (std::size_t i = 1; i < points.size(); i += 2)
        draw->AddLine(points[i - 1], points[i], s.colour, 2.0f);
    } else if (points.size() > 1) {
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.colour, 0, 2.0f);
    }
  }
  draw->PopClipRect();
  draw->AddRect(ImVec2(left, top), ImVec2(right, bottom), frame);
  // Legend, top right.
  float ly = top + 3;
  if (series.size() > 1) {
    for (const auto& s : series) {
      const float w = ImGui::CalcTextSize(s.label.c_str()).x;
      draw->AddLine(ImVec2(right - w - 24, ly + font / 2), ImVec2(right - w - 8, ly + font / 2),
                    s.colour, 2.0f);
      draw->AddText(ImVec2(right - w - 4, ly), text, s.label.c_str());
      ly += font;
    }
  }
  if (!hovered) return std::numeric_limits<double>::quiet_NaN();
  const float mx = ImGui::GetIO().MousePos.x;
  if (mx < left || mx > right) return std::numeric_limits<double>::quiet_NaN();
  const double x = x0 + (mx - left) / (right - left) * (x1 - x0);
  draw->AddLine(ImVec2(mx, top), ImVec2(mx, bottom), IM_COL32(255, 255, 255, 120));
  std::string tip;
  char line[128];
  std::snprintf(line, sizeof line, "%.1f %s", x, o.x_label.c_str());
  tip += line;
  for (const auto& s : series) {
    std::snprintf(line, sizeof line, "\n%s: %.5g", s.label.c_str(), series_at(s, x));
    tip += line;
  }
  ImGui::SetTooltip("%s", tip.c_str());
  return x;
}

}  // namespace impasto::app::window
