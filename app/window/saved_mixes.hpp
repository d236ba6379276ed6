#pragma once
// Saved mixes: mixes the painter keeps across sessions, named, shown as chips in the paint
// strip (paint_strip.hpp). They live in one small text file, window_config_folder() /
// "mixes.txt" (~/.config/impasto/mixes.txt):
//
//   impasto-mixes 1
//   mix Sea green
//   part 4.3 Green
//   part 3.8 Cold Yellow
//   part 1.9 White
//
// A mix is named by its pigments, not their places in the library, so a library that changes
// keeps the mixes whose pigments it still has. Names are written line-encoded (util/text.hpp).
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace impasto::app::window {

inline constexpr std::size_t kMaxSavedMixes = 64;  // a file with more is cut there, with a note

struct SavedMix {
  std::string name;
  std::vector<std::pair<std::string, float>> parts;  // pigment name, parts (> 0)
  bool operator==(const SavedMix&) const = default;
};

struct SavedMixes {
  std::vector<SavedMix> mixes;
  std::vector<std::string> warnings;  // what was passed over, each naming its source and line
};

// The file's text. A line that is not a header, `mix NAME` or `part PARTS PIGMENT` (parts
// finite, in (0, 1000]), or a part before any mix, is an error: "SOURCE:LINE: ...", thrown as
// std::runtime_error. A part whose pigment `known` does not name is passed over with a
// warning, and so is a mix left with no parts.
SavedMixes parse_saved_mixes(std::string_view text, const std::string& source,
                             const std::vector<std::string>& known);
std::string format_saved_mixes(const std::vector<SavedMix>& mixes);

// The file (none: no mixes); its problems as warnings, never an exception.
std::filesystem::path saved_mixes_path();  // empty without XDG_CONFIG_HOME or HOME
SavedMixes load_saved_mixes(const std::vector<std::string>& known);
// Written atomically; throws std::runtime_error naming the file when it cannot be.
void store_saved_mixes(const std::vector<SavedMix>& mixes);

// The mix of Palette parts (per pigment of the library, `known` in its order) as a saved mix,
// and back.
SavedMix saved_mix(std::string name, const std::vector<float>& mix_parts,
                   const std::vector<std::string>& known);
std::vector<float> mix_parts_of(const SavedMix& mix, const std::vector<std::string>& known);
// "4.3 Green + 3.8 Cold Yellow + 1.9 White": a mix's name when the painter gives none.
std::string mix_description(const SavedMix& mix);

}  // namespace impasto::app::window
