#pragma once
// `impasto pigments plot`: a pigment's K, S, K/S and R∞ curves and its swatches as one
// figure, written as SVG (text and vectors) or PNG (rasterised here, text in ImGui's built-in
// font where the window is built).
#include <impasto/data/pigments.hpp>
#include <impasto/data/spectrum.hpp>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace impasto::app {

// Vector primitives in pixels, y down.
struct Figure {
  using Rgb = std::array<double, 3>;  // 0..1, display-encoded
  struct Line {
    std::vector<std::array<double, 2>> points;
    Rgb colour;
    double width;
  };
  struct Box {
    double x, y, w, h;
    Rgb fill;
    bool outline;
  };
  struct Text {
    double x, y;  // baseline start (anchor start) or middle (anchor middle)
    std::string text;
    Rgb colour;
    bool centred;
  };
  int width = 0, height = 0;
  std::vector<Box> boxes;  // drawn first
  std::vector<Line> lines;
  std::vector<Text> texts;
};

// The pigment's figure: three plots and the swatch row under `light` (white: the tints').
Figure pigment_figure(const data::Pigment& pigment, const std::string& subtitle,
                      const data::Pigment& white, const data::Spectrum& light,
                      const std::string& light_name);

std::string figure_svg(const Figure& figure);
// By extension: .svg or .png; written atomically. Throws naming the file.
void write_figure(const std::filesystem::path& path, const Figure& figure);

}  // namespace impasto::app
