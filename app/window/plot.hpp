#pragma once
// One small plot on ImDrawList (Debian has no ImGui plotting library): axes with round-number
// ticks, curves, a legend, marker lines (a light's wavelength nodes) and a hover read-out of
// every curve at the mouse's x. Used by the Light panel and the Pigment editor.
#include <imgui.h>

#include <limits>
#include <span>
#include <string>
#include <vector>

namespace impasto::app::window {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // same length; x increasing
  ImU32 colour = IM_COL32(230, 230, 230, 255);
  bool dashed = false;  // e.g. the fitted curve against the measured one
};

struct PlotOptions {
  const char* id = "##plot";
  ImVec2 size{300, 160};
  std::string title, x_label = "nm";
  std::vector<double> markers_x;  // vertical lines (the light's wavelength nodes)
  // The y range: from y_min (or the data's smallest) to the data's largest, or y_max.
  double y_min = 0.0;
  bool y_min_from_data = false;
  double y_max = std::numeric_limits<double>::quiet_NaN();
};

// Draws the plot as one item (hover shows a tooltip). Returns the x under the mouse, or NaN.
double draw_plot(const PlotOptions& options, std::span<const PlotSeries> series);

// The value of a series at x (linear between points, held at the ends).
double series_at(const PlotSeries& series, double x);

}  // namespace impasto::app::window
