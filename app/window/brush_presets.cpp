#include "window/brush_presets.hpp"

#include <impasto/files/atomic_file.hpp>
#include <impasto/files/data_dir.hpp>
#include <impasto/files/input_file.hpp>
#include <impasto/paintcore/paint_body.hpp>
#include <impasto/util/text.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "impasto/session/recent_files.hpp"

namespace impasto::app::window {
namespace {

constexpr std::array<std::string_view, 8> kPresetKeys{
    "name", "head", "size_mm", "stiffness", "body", "load_mm3", "pressure", "pressure_from_speed"};

constexpr std::size_t kMaxPresetNameLength = 64;

// A number in [low, high], or nullopt.
std::optional<double> number_in(std::string_view text, double low, double high) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value < low || value > high) {
    return std::nullopt;
  }
  return value;
}

std::string format_number(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::to_string(value);
}

std::string key_list() {
  std::string list;
  for (std::string_view key : kPresetKeys) {
    if (!list.empty()) list += ", ";
    list += key;
  }
  return list;
}

}  // namespace

std::span<const std::string_view> preset_keys() {
  return kPresetKeys;
}

BrushPreset parse_brush_preset(std::string_view text, const std::string& source) {
  BrushPreset preset;
  std::map<std::string_view, int> seen;  // key -> its line
  int line_number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = util::trim(text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
    ++line_number;
    const std::string where = source + ":" + std::to_string(line_number) + ": ";
    if (line.empty() || line.front() == '#') continue;
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos)
      throw std::runtime_error(where + "expected `key = value`, found '" + std::string(line) + "'");
    const std::string_view key = util::trim(line.substr(0, equals));
    const std::string_view value = util::trim(line.substr(equals + 1));
    const auto known = std::find(kPresetKeys.begin(), kPresetKeys.end(), key);
    if (known == kPresetKeys.end())
      throw std::runtime_error(where + "unknown key '" + std::string(key) +
                               "' (the keys: " + key_list() + ")");
    if (const auto before = seen.find(*known); before != seen.end())
      throw std::runtime_error(where + "'" + std::string(key) + "' again (first on line " +
                               std::to_string(before->second) + ")");
    seen[*known] = line_number;
    const auto bad = [&](const std::string& expected) {
      return std::runtime_error(where + std::string(key) + ": '" + std::string(value) +
                                "' is not " + expected);
    };
    if (key == "name") {
      if (value.empty() || value.size() > kMaxPresetNameLength)
        throw bad("a name of 1 to " + std::to_string(kMaxPresetNameLength) + " characters");
      preset.name = value;
    } else if (key == "head") {
      if (value.empty() || value.find('/') != std::string_view::npos)
        throw bad("a brush head's name (a .brush file of the brushes folder, without .brush)");
      preset.head = value;
    } else if (key == "size_mm") {
      const auto size = number_in(value, kBrushSizeMinMm, kBrushSizeMaxMm);
      if (!size)
        throw bad("a size from " + format_number(kBrushSizeMinMm) + " to " +
                  format_number(kBrushSizeMaxMm) + " mm");
      preset.size_mm = *size;
    } else if (key == "stiffness") {
      const auto stiffness = number_in(value, 0.0, 1.0);
      if (!stiffness) throw bad("a stiffness from 0 to 1");
      preset.stiffness = *stiffness;
    } else if (key == "body") {
      if (!paintcore::paint_body_from_name(value))
        throw bad("a paint body (" + paintcore::paint_body_names() + ")");
      preset.body = value;
    } else if (key == "load_mm3") {
      const auto load = number_in(value, kLoadMinMm3, kLoadMaxMm3);
      if (!load)
        throw bad("a load from " + format_number(kLoadMinMm3) + " to " +
                  format_number(kLoadMaxMm3) + " mm³");
      preset.load_mm3 = *load;
    } else if (key == "pressure") {
      const auto pressure = number_in(value, 0.05, 1.0);
      if (!pressure) throw bad("a pressure from 0.05 to 1");
      preset.pressure = static_cast<float>(*pressure);
    } else if (key == "pressure_from_speed") {
      if (value != "true" && value != "false") throw bad("true or false");
      preset.pressure_from_speed = value == "true";
    }
  }
  for (std::string_view key : kPresetKeys)
    if (!seen.contains(key))
      throw std::runtime_error(source + ": no '" + std::string(key) + "' (a preset gives " +
                               key_list() + ")");
  return preset;
}

std::string format_brush_preset(const BrushPreset& p) {
  return "# Impasto brush preset (docs/window.md, \"Brush presets\")\n"
         "name = " +
         p.name + "\nhead = " + p.head + "\nsize_mm = " + format_number(p.size_mm) +
         "\nstiffness = " + format_number(p.stiffness) + "\nbody = " + p.body +
         "\nload_mm3 = " + format_number(p.load_mm3) +
         "\npressure = " + format_number(static_cast<double>(p.pressure)) +
         "\npressure_from_speed = " + (p.pressure_from_speed ? "true" : "false") + "\n";
}

BrushPreset read_brush_preset(const std::filesystem::path& file) {
  constexpr std::uint64_t kMaxPresetBytes = 64 << 10;  // a preset is a few lines
  BrushPreset preset = parse_brush_preset(
      files::read_whole_file(file, "brush preset", kMaxPresetBytes), file.string());
  preset.file = file;
  return preset;
}

void write_brush_preset(const BrushPreset& preset, const std::filesystem::path& file) {
  // What is written must read back: the same checks as a file's.
  parse_brush_preset(format_brush_preset(preset), file.string());
  std::filesystem::create_directories(file.parent_path());
  files::write_file_atomically(file, format_brush_preset(preset));
}

std::filesystem::path shipped_presets_dir() {
  return files::data_dir() / "presets";
}

std::filesystem::path user_presets_dir() {
  const std::filesystem::path folder = session::window_config_folder();
  return folder.empty() ? folder : folder / "presets";
}

std::string preset_file_name(const std::string& name) {
  std::string file;
  for (const char c : name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0;
    if (keep) {
      file += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!file.empty() && file.back() != '-') {
      file += '-';
    }
  }
  while (!file.empty() && file.back() == '-') file.pop_back();
  return (file.empty() ? std::string("preset") : file) + ".preset";
}

PresetLibrary load_brush_presets(const std::filesystem::path& shipped,
                                 const std::filesystem::path& user,
                                 std::span<const std::string> heads) {
  PresetLibrary library;
  for (const auto& [folder, is_user] : {std::pair{shipped, false}, std::pair{user, true}}) {
    if (folder.empty()) continue;
    std::error_code error;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
      if (entry.path().extension() == ".preset") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      try {
        BrushPreset preset = read_brush_preset(file);
        if (std::find(heads.begin(), heads.end(), preset.head) == heads.end())
          throw std::runtime_error(file.string() + ": head '" + preset.head +
                                   "' is not among the brushes");
        preset.user = is_user;
        std::erase_if(library.presets,
                      [&](const BrushPreset& other) { return other.name == preset.name; });
        library.presets.push_back(std::move(preset));
      } catch (const std::exception& e) {
        library.errors.push_back(e.what());
      }
    }
  }
  return library;
}

}  // namespace impasto::app::window
