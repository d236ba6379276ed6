#pragma once
// The short session the command-line, window and session tests replay: three strokes of a
// loaded round brush (blue, red, white) on a 240 x 160-cell canvas at 254 dpi, as a stroke
// file (docs/stroke-format.md) or, for a test that plays it in process, as its numbers.
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <vector>

namespace impasto::test {

struct ShortSession {
  static constexpr int kWidthCells = 240, kHeightCells = 160;
  static constexpr double kDpi = 254;
  static constexpr const char* kBrush = "round";
  static constexpr double kBrushSizeMm = 4, kBrushStiffness = 0.5;
  static constexpr double kLoadMm3 = 30;    // each stroke wipes the brush and loads this
  static constexpr double kPressure = 0.7;  // while the tip is down
  static constexpr std::array<const char*, 3> kPigments = {"Blue Red Shade", "Red", "White"};
  struct Pen {
    double time_s, x_mm, y_mm;
    bool down;  // the last sample of a stroke lifts the tip
  };
  // The pen samples of each stroke (one a pigment), the times running on through all three.
  static std::array<std::vector<Pen>, 3> strokes() {
    std::array<std::vector<Pen>, 3> pens;
    double t = 0;
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i <= 40; ++i, t += 0.01)
        pens[k].push_back({t, 2 + 0.45 * i, 4.0 + 4 * k, i < 40});
    }
    return pens;
  }
};

// Writes it to `path` as a stroke file and returns `path`.
inline std::filesystem::path write_short_session(const std::filesystem::path& path) {
  using S = ShortSession;
  std::ofstream out(path);
  out << "impasto-strokes 2\ncanvas " << S::kWidthCells << " " << S::kHeightCells << " " << S::kDpi
      << "\nbrush " << S::kBrush << " size=" << S::kBrushSizeMm
      << " stiffness=" << S::kBrushStiffness << "\n";
  const auto strokes = S::strokes();
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    out << "wipe\nload " << S::kLoadMm3 << " \"" << S::kPigments[k] << "\" 1\n";
    for (const S::Pen& pen : strokes[k]) {
      out << "pen " << pen.time_s << " " << pen.x_mm << " " << pen.y_mm << " "
          << (pen.down ? S::kPressure : 0) << " 0 0 0 " << (pen.down ? 17 : 16) << "\n";
    }
  }
  return path;
}

}  // namespace impasto::test
