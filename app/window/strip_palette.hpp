#pragma once
// The painter's palette: which of the library's paints the paint strip shows, in the library's
// order (paint_strip.hpp). Kept in window_config_folder() / "palette.txt":
//
//   impasto-palette 1
//   hide Aluminium Metallic
//   hide Mica Blue Pearl
//
// (the paints left out, names line-encoded), so that paints added to the library later show
// until the painter hides them. No file: every paint shows.
#include <string>
#include <string_view>
#include <vector>

namespace impasto::app::window {

struct StripPalette {
  std::vector<std::string> hidden;  // paint names, each once
  std::vector<std::string> warnings;
  bool shows(const std::string& paint) const;
};

// The file's text: a line that is not the header or `hide NAME` is an error, thrown as
// std::runtime_error "SOURCE:LINE: ..."; a name given twice counts once.
StripPalette parse_strip_palette(std::string_view text, const std::string& source);
std::string format_strip_palette(const StripPalette& palette);

// The painter's file (none: every paint shows); its problems as warnings, never an exception.
StripPalette load_strip_palette();
// Written atomically; throws std::runtime_error naming the file when it cannot be.
void store_strip_palette(const StripPalette& palette);

}  // namespace impasto::app::window
