// Brush presets: the file format (every bad input is an error naming the file and the line),
// the round trip, and the library of shipped and user folders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "window/brush_presets.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

const std::string kGood =
    "# a comment\n"
    "name = Impasto round\n"
    "head = round\n"
    "size_mm = 10\n"
    "stiffness = 0.7\n"
    "\n"
    "body = paste\n"
    "load_mm3 = 300\n"
    "pressure = 0.8\n"
    "pressure_from_speed = false\n";

// The message parsing `text` throws ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse_brush_preset(text, "my.preset");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// kGood with line `line` (1-based) replaced.
std::string with_line(int line, const std::string& replacement) {
  std::string text;
  int number = 0;
  std::size_t start = 0;
  while (start < kGood.size()) {
    const std::size_t end = kGood.find('\n', start);
    ++number;
    text += (number == line ? replacement : kGood.substr(start, end - start)) + "\n";
    start = end + 1;
  }
  return text;
}

TEST(BrushPresetFile, ParsesEveryKey) {
  const BrushPreset p = parse_brush_preset(kGood, "my.preset");
  EXPECT_EQ(p.name, "Impasto round");
  EXPECT_EQ(p.head, "round");
  EXPECT_EQ(p.size_mm, 10.0);
  EXPECT_EQ(p.stiffness, 0.7);
  EXPECT_EQ(p.body, "paste");
  EXPECT_EQ(p.load_mm3, 300.0);
  EXPECT_FLOAT_EQ(p.pressure, 0.8f);
  EXPECT_FALSE(p.pressure_from_speed);
  // CRLF lines read the same.
  std::string crlf;
  for (char c : kGood) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(parse_brush_preset(crlf, "my.preset"), p);
}

TEST(BrushPresetFile, BadInputNamesTheFileTheLineAndWhatWasExpected) {
  struct Case {
    int line;
    std::string replacement, expected;
  };
  const std::vector<Case> cases{
      {4, "size_mm = big", "my.preset:4: size_mm: 'big' is not a size from 0.1 to 1000 mm"},
      {4, "size_mm = 0.05", "my.preset:4: size_mm"},
      {4, "size_mm = 1e999", "my.preset:4: size_mm"},
      {4, "size_mm = nan", "my.preset:4: size_mm"},
      {4, "size_mm = 10 mm", "my.preset:4: size_mm"},
      {5, "stiffness = 1.5", "my.preset:5: stiffness: '1.5' is not a stiffness from 0 to 1"},
      {7, "body = runny", "my.preset:7: body: 'runny' is not a paint body (fluid, soft"},
      {8, "load_mm3 = 0", "my.preset:8: load_mm3"},
      {9, "pressure = -1", "my.preset:9: pressure"},
      {10, "pressure_from_speed = yes", "my.preset:10: pressure_from_speed: 'yes' is not true"},
      {3, "head = ../../etc/x", "my.preset:3: head"},
      {2, "name =", "my.preset:2: name"},
      {6, "colour = red", "my.preset:6: unknown key 'colour' (the keys: name, head,"},
      {6, "just words", "my.preset:6: expected `key = value`, found 'just words'"},
      {6, "size_mm = 3", "my.preset:6: 'size_mm' again (first on line 4)"},
      {5, "# stiffness left out", "my.preset: no 'stiffness'"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(with_line(c.line, c.replacement));
    EXPECT_EQ(message.rfind(c.expected, 0), 0u)
        << "line " << c.line << " '" << c.replacement << "': " << message;
  }
  EXPECT_EQ(error_of(""),
            "my.preset: no 'name' (a preset gives name, head, size_mm, stiffness, "
            "body, load_mm3, pressure, pressure_from_speed)");
}

TEST(BrushPresetFile, WhatIsWrittenReadsBackTheSame) {
  BrushPreset p;
  p.name = "Glaze flat, wide";
  p.head = "flat";
  p.size_mm = 21.37;
  p.stiffness = 0.3;
  p.body = "fluid";
  p.load_mm3 = 61.5;
  p.pressure = 0.45f;
  p.pressure_from_speed = true;
  EXPECT_EQ(parse_brush_preset(format_brush_preset(p), "x"), p);
  const fs::path dir = fs::temp_directory_path() / ("impasto_presets_" + std::to_string(getpid()));
  const fs::path file = dir / "user" / preset_file_name(p.name);
  EXPECT_EQ(file.filename(), "glaze-flat-wide.preset");
  write_brush_preset(p, file);
  BrushPreset read = read_brush_preset(file);
  EXPECT_EQ(read.file, file);
  read.file.clear();
  EXPECT_EQ(read, p);
  // A preset that could not be read back is not written.
  p.size_mm = 1001.0;  // over paintcore::kMaxBrushSizeMm
  EXPECT_THROW(write_brush_preset(p, dir / "user" / "bad.preset"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "user" / "bad.preset"));
  fs::remove_all(dir);
}

TEST(BrushPresetLibrary, UserPresetsReplaceShippedOnesAndBadFilesAreReported) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_preset_library_" + std::to_string(getpid()));
  const std::vector<std::string> heads{"flat", "knife", "round"};
  BrushPreset round = parse_brush_preset(kGood, "x");
  write_brush_preset(round, dir / "shipped" / "impasto-round.preset");
  BrushPreset knife = round;
  knife.name = "Knife";
  knife.head = "knife";
  write_brush_preset(knife, dir / "shipped" / "knife.preset");
  BrushPreset mine = round;
  mine.size_mm = 3.0;
  write_brush_preset(mine, dir / "user" / "mine.preset");  // named "Impasto round" too
  BrushPreset fan = round;
  fan.name = "Fan";
  fan.head = "fan";  // not among `heads`
  write_brush_preset(fan, dir / "user" / "fan.preset");
  std::ofstream(dir / "user" / "broken.preset") << "name = Broken\nhead round\n";

  const PresetLibrary library = load_brush_presets(dir / "shipped", dir / "user", heads);
  ASSERT_EQ(library.presets.size(), 2u);
  EXPECT_EQ(library.presets[0].name, "Knife");
  EXPECT_FALSE(library.presets[0].user);
  EXPECT_EQ(library.presets[1].name, "Impasto round");
  EXPECT_TRUE(library.presets[1].user);
  EXPECT_EQ(library.presets[1].size_mm, 3.0);
  ASSERT_EQ(library.errors.size(), 2u);
  EXPECT_NE(library.errors[0].find("broken.preset:2: expected `key = value`"), std::string::npos)
      << library.errors[0];
  EXPECT_NE(library.errors[1].find("fan.preset: head 'fan' is not among the brushes"),
            std::string::npos)
      << library.errors[1];
  // Missing folders are no error.
  EXPECT_TRUE(load_brush_presets(dir / "none", {}, heads).errors.empty());
  fs::remove_all(dir);
}

// The shipped set: every file reads, every head is a shipped brush, the names differ.
TEST(BrushPresetLibrary, TheShippedPresetsAllLoad) {
  const fs::path data = fs::path(IMPASTO_SOURCE_DIR) / "data";
  std::vector<std::string> heads;
  for (const auto& entry : fs::directory_iterator(data / "brushes"))
    if (entry.path().extension() == ".brush") heads.push_back(entry.path().stem().string());
  const PresetLibrary library = load_brush_presets(data / "presets", {}, heads);
  EXPECT_TRUE(library.errors.empty()) << library.errors.front();
  EXPECT_GE(library.presets.size(), heads.size());
  for (const std::string& head : heads) {
    EXPECT_TRUE(std::any_of(library.presets.begin(), library.presets.end(),
                            [&](const BrushPreset& p) { return p.head == head; }))
        << "no preset for the " << head << " head";
  }
}

}  // namespace
}  // namespace impasto::app::window
