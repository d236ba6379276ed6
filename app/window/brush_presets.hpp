#pragma once
// Brush presets: a named brush as the Brush and Palette panels set it (head, size, stiffness,
// the paint's body and load, the mouse's pressure), one small text file each:
//
//   # a comment
//   name = Impasto round
//   head = round
//   size_mm = 10
//   ...
//
// (every key of kPresetKeys, once each). The shipped set is data/presets/ (files::data_dir());
// the user's own go to $XDG_CONFIG_HOME/impasto/presets (~/.config/impasto/presets), where a
// preset of the same name replaces a shipped one. docs/window.md, "Brush presets".
#include <impasto/paintcore/brush.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::app::window {

// The ranges the panels offer, and the brush size keys' step ([ and ]). The size goes up to the
// engine's most (less on a fine canvas: paintcore::max_brush_size_mm) from a tenth of a
// millimetre, the finest a hand sets in the window (a stroke file may go finer).
inline constexpr double kBrushSizeMinMm = 0.1;
inline constexpr double kBrushSizeMaxMm = paintcore::kMaxBrushSizeMm;
inline constexpr double kBrushSizeStep = 1.25;  // six steps double the size, near enough
inline constexpr double kLoadMinMm3 = 1.0, kLoadMaxMm3 = 400.0;

struct BrushPreset {
  std::string name;
  std::string head;  // a .brush of the brushes folder
  double size_mm = 6.0;
  double stiffness = 0.5;
  std::string body = "heavy";  // paint_body.hpp's names
  double load_mm3 = 40.0;
  float pressure = 0.6f;  // the mouse's, when not from speed
  bool pressure_from_speed = false;
  // Where it was read from; `user`: from the user's folder (the window may delete it).
  std::filesystem::path file;
  bool user = false;
  bool operator==(const BrushPreset&) const = default;
};

// The keys of a preset file, in the order they are written.
std::span<const std::string_view> preset_keys();

// A preset file's text. Throws std::runtime_error "SOURCE:LINE: ..." for a line that is not
// `key = value`, an unknown or repeated key, a value out of range; "SOURCE: ..." for a
// missing key.
BrushPreset parse_brush_preset(std::string_view text, const std::string& source);
std::string format_brush_preset(const BrushPreset& preset);
BrushPreset read_brush_preset(const std::filesystem::path& file);
// Written atomically (files::write_file_atomically); the folder is made when missing.
void write_brush_preset(const BrushPreset& preset, const std::filesystem::path& file);

std::filesystem::path shipped_presets_dir();  // files::data_dir() / "presets"
std::filesystem::path user_presets_dir();     // empty when neither variable is set
// "Impasto round" -> "impasto-round.preset": letters and digits, the rest as '-'.
std::string preset_file_name(const std::string& name);

struct PresetLibrary {
  std::vector<BrushPreset> presets;  // shipped first, by name, then the user's
  std::vector<std::string> errors;   // files that could not be read, each naming the file
};
// Every *.preset of both folders (a missing folder is no error). A preset whose head is not
// in `heads` is an error, not a preset: it could not be applied.
PresetLibrary load_brush_presets(const std::filesystem::path& shipped,
                                 const std::filesystem::path& user,
                                 std::span<const std::string> heads);

}  // namespace impasto::app::window
