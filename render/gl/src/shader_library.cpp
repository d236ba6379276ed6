#include "impasto/render_gl/shader_library.hpp"

#include <cstdio>
#include <string>

#include "embedded_shaders.hpp"
#include "impasto/flakes/flake_tables.hpp"
#include "impasto/paintcore/crack_layer.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render_gl/flake_textures.hpp"

namespace impasto::render_gl {
namespace {

// A float constant as GLSL text that parses back to the same float.
std::string glsl_float(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string s = text;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// Sizes the shaders share with the C++ (they are #defined from it below); the GPU holds no
// more flake pigments than a painting has slots, and each crack shape has its deepest row.
static_assert(FlakeTextures::kMaxFlakePigments <= paintcore::kMaxPigmentSlots);
static_assert(std::tuple_size_v<decltype(render::CrackTableData::last_F)> ==
              paintcore::kCrackShapeCount);

}  // namespace

const char* optics_glsl() {
  return shaders::optics_lib;
}

const char* km_glsl() {
  return shaders::km_lib;
}

const char* shading_glsl() {
  static const std::string source = "#define SHADE_OCCLUSION_DIRECT_SHARE " +
                                    glsl_float(render::shade::kOcclusionDirectShare) + "\n" +
                                    shaders::shading_lib;
  return source.c_str();
}

const char* flakes_glsl() {
  static const std::string source =
      "#define MAX_FLAKES " + std::to_string(FlakeTextures::kMaxFlakePigments) +
      "\n#define FLAKE_ORIENTATION_SAMPLES " +
      std::to_string(flakes::FlakeTables::kOrientationSamples) + "\n#define FLAKE_ANGLE_SAMPLES " +
      std::to_string(flakes::FlakeTables::kAngleSamples) + "\n" + shaders::optics_lib +
      shaders::flakes_lib;
  return source.c_str();
}

const char* cracks_glsl() {
  static const std::string source = "#define CRACK_SHAPES " +
                                    std::to_string(paintcore::kCrackShapeCount) + "\n" +
                                    shaders::cracks_lib;
  return source.c_str();
}

const char* relief_glsl() {
  static const std::string source = "#define RELIEF_DIRECTIONS " +
                                    std::to_string(render::relief::kOcclusionDirections) + "\n" +
                                    shaders::relief_lib;
  return source.c_str();
}

}  // namespace impasto::render_gl
