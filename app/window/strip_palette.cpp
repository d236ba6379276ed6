#include "window/strip_palette.hpp"

#include <impasto/util/text.hpp>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "impasto/files/message_text.hpp"
#include "impasto/session/recent_files.hpp"
#include "window/config_files.hpp"

namespace impasto::app::window {
namespace {

constexpr std::string_view kPaletteHeader = "impasto-palette 1";
constexpr std::size_t kPaletteMaxBytes = 1 << 16;  // a library of hundreds of paints fits

}  // namespace

bool StripPalette::shows(const std::string& paint) const {
  return std::find(hidden.begin(), hidden.end(), paint) == hidden.end();
}

StripPalette parse_strip_palette(std::string_view text, const std::string& source) {
  StripPalette palette;
  std::istringstream in{std::string(text)};
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string_view trimmed = util::trim(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    const std::string where = source + ":" + std::to_string(number) + ": ";
    if (trimmed == kPaletteHeader) continue;
    if (number == 1)
      throw std::runtime_error(where + "expected '" + std::string(kPaletteHeader) + "'");
    if (!trimmed.starts_with("hide "))
      throw std::runtime_error(where + "expected 'hide NAME', got '" +
                               files::terminal_text(std::string(trimmed.substr(0, 40))) + "'");
    const std::string name = util::line_decoded(util::trim(trimmed.substr(5)));
    if (palette.shows(name)) palette.hidden.push_back(name);
  }
  return palette;
}

std::string format_strip_palette(const StripPalette& palette) {
  std::string text = std::string(kPaletteHeader) + "\n";
  for (const std::string& name : palette.hidden) text += "hide " + util::line_encoded(name) + "\n";
  return text;
}

StripPalette load_strip_palette() {
  std::string warning;
  const std::string text = read_config_text("palette.txt", kPaletteMaxBytes, warning);
  if (!warning.empty()) return {{}, {warning}};
  try {
    return parse_strip_palette(text, (session::window_config_folder() / "palette.txt").string());
  } catch (const std::exception& e) {
    return {{}, {std::string(e.what()) + " (every paint shown)"}};
  }
}

void store_strip_palette(const StripPalette& palette) {
  write_config_text("palette.txt", format_strip_palette(palette));
}

}  // namespace impasto::app::window
