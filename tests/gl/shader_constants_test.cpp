// The sizes the GLSL shares with the C++ are #defined into the shaders from the C++ at
// compile time (shader_library.cpp, canvas_renderer.cpp). These tests fail when a shader
// writes one of them again by hand, or when an injected value differs from its C++ twin.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

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
  const std::regex define("#define " + name + " ([^\\n]+)\\n");
  std::smatch match;
  return std::regex_search(source, match, define) ? match[1].str() : "";
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
  const std::regex redefined(
      "(#define|const\\s+\\w+)\\s+(MAX_NODES|MAX_SLOTS|MAX_FLAKES|FLAKE_ORIENTATION_SAMPLES|"
      "FLAKE_ANGLE_SAMPLES|CRACK_SHAPES|RELIEF_DIRECTIONS|SHADE_OCCLUSION_DIRECT_SHARE)\\b");
  // The values of the table sizes and the shape count, written as numbers.
  const std::string sizes = std::to_string(flakes::FlakeTables::kOrientationSamples) + "|" +
                            std::to_string(flakes::FlakeTables::kAngleSamples);
  const std::regex literal_size("[^.\\w](" + sizes + ")[^.\\w]");
  const std::regex literal_shapes("\\[" + std::to_string(paintcore::kCrackShapeCount) + "\\]");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".glsl") continue;
    ++files;
    const std::string code = code_of(entry.path());
    EXPECT_FALSE(std::regex_search(code, redefined)) << entry.path();
    EXPECT_FALSE(std::regex_search(code, literal_size)) << entry.path();
    EXPECT_FALSE(std::regex_search(code, literal_shapes)) << entry.path();
  }
  EXPECT_GT(files, 5);
}

}  // namespace
}  // namespace impasto::render_gl
