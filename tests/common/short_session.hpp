#pragma once
// The short session the command-line and window tests replay: three strokes of a loaded
// round brush (blue, red, white) on a 240 x 160-cell canvas at 254 dpi, as a stroke file
// (docs/stroke-format.md).
#include <filesystem>
#include <fstream>

namespace impasto::test {

// Writes it to `path` and returns `path`.
inline std::filesystem::path write_short_session(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "impasto-strokes 2\ncanvas 240 160 254\nbrush round size=4 stiffness=0.5\n";
  const char* pigments[] = {"Ultramarine Blue", "Pyrrole Red", "Titanium White"};
  double t = 0;
  for (int k = 0; k < 3; ++k) {
    out << "wipe\nload 30 \"" << pigments[k] << "\" 1\n";
    for (int i = 0; i <= 40; ++i, t += 0.01) {
      const bool down = i < 40;
      out << "pen " << t << " " << 2 + 0.45 * i << " " << 4 + 4 * k << " " << (down ? 0.7 : 0)
          << " 0 0 0 " << (down ? 17 : 16) << "\n";
    }
  }
  return path;
}

}  // namespace impasto::test
