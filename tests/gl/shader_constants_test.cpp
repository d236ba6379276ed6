// The sizes the GLSL shares with the C++ are #defined into the shaders from the C++ at
// compile time (shader_library.cpp, canvas_renderer.cpp). These tests fail when a shader
// writes one of them again by hand, or when an injected value differs from its C++ twin.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "impasto/flakes/flake_tables.hpp"
#include "impasto/paintcore/crack_layer.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render_gl/flake_textures.hpp"
#include "impasto/render_gl/shader_library.hpp"

namespace impasto::render_gl {
namespace {

namespace fs = std::filesystem;

// The value of `#define NAME VALUE` in an assembled source; "" when it is not there.
std::string defined_value(const std::string& source, const std::string& name) {
  const std::string key = "#define " + name + " ";
  std::istringstream lines(source);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  }
  return "";
}

// The code's words (letters, digits, '_', '.' and a leading '#') and its other characters,
// one token each; blanks separate tokens and are dropped.
std::vector<std::string> tokens_of(const std::string& code) {
  const auto word_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  };
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < code.size();) {
    const char c = code[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (word_char(c) || c == '#') {
      std::size_t end = i + 1;
      while (end < code.size() && word_char(code[end])) ++end;
      tokens.push_back(code.substr(i, end - i));
      i = end;
    } else {
      tokens.emplace_back(1, c);
      ++i;
    }
  }
  return tokens;
}

// A shader file without its // comments.
std::string code_of(const fs::path& file) {
  std::ifstream in(file);
  std::string line, code;
  while (std::getline(in, line)) code += line.substr(0, line.find("//")) + "\n";
  return code;
}

TEST(ShaderConstants, TheInjectedValuesAreTheCppOnes) {
  EXPECT_EQ(defined_value(flakes_glsl(), "MAX_FLAKES"),
            std::to_string(FlakeTextures::kMaxFlakePigments));
  EXPECT_EQ(defined_value(flakes_glsl(), "FLAKE_ORIENTATION_SAMPLES"),
            std::to_string(flakes::FlakeTables::kOrientationSamples));
  EXPECT_EQ(defined_value(flakes_glsl(), "FLAKE_ANGLE_SAMPLES"),
            std::to_string(flakes::FlakeTables::kAngleSamples));
  EXPECT_EQ(defined_value(cracks_glsl(), "CRACK_SHAPES"),
            std::to_string(paintcore::kCrackShapeCount));
  EXPECT_EQ(defined_value(relief_glsl(), "RELIEF_DIRECTIONS"),
            std::to_string(render::relief::kOcclusionDirections));
}

TEST(ShaderConstants, NoShaderWritesAnInjectedConstantByHand) {
  const fs::path folder = fs::path(IMPASTO_SOURCE_DIR) / "render/gl/shaders";
  // Names the C++ defines; a shader that defines one again would hide a disagreement.
  const std::set<std::string> injected{
      "MAX_NODES",           "MAX_SLOTS",    "MAX_FLAKES",        "FLAKE_ORIENTATION_SAMPLES",
      "FLAKE_ANGLE_SAMPLES", "CRACK_SHAPES", "RELIEF_DIRECTIONS", "SHADE_OCCLUSION_DIRECT_SHARE"};
  // The values of the table sizes and the shape count, written as numbers.
  const std::set<std::string> sizes{std::to_string(flakes::FlakeTables::kOrientationSamples),
                                    std::to_string(flakes::FlakeTables::kAngleSamples)};
  const std::string shapes = std::to_string(paintcore::kCrackShapeCount);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".glsl") continue;
    ++files;
    const std::vector<std::string> t = tokens_of(code_of(entry.path()));
    for (std::size_t i = 0; i < t.size(); ++i) {
      const bool defines = t[i] == "#define" && i + 1 < t.size() && injected.count(t[i + 1]);
      const bool declares = t[i] == "const" && i + 2 < t.size() && injected.count(t[i + 2]);
      EXPECT_FALSE(defines || declares)
          << entry.path() << ": " << t[i] << " " << (declares ? t[i + 2] : t[i + 1]);
      EXPECT_FALSE(sizes.count(t[i])) << entry.path() << ": the number " << t[i];
      const bool shape_array =
          t[i] == "[" && i + 2 < t.size() && t[i + 1] == shapes && t[i + 2] == "]";
      EXPECT_FALSE(shape_array) << entry.path() << ": [" << shapes << "]";
    }
  }
  EXPECT_GT(files, 5);
}

}  // namespace
}  // namespace impasto::render_gl
