#include "impasto/render_gl/shader_library.hpp"

#include <cstdio>
#include <string>

#include "embedded_shaders.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/shading.hpp"

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

}  // namespace

const char* km_glsl() {
  return shaders::km_lib;
}

const char* shading_glsl() {
  static const std::string source = "#define SHADE_OCCLUSION_DIRECT_SHARE " +
                                    glsl_float(render::shade::kOcclusionDirectShare) + "\n" +
                                    shaders::shading_lib;
  return source.c_str();
}

const char* relief_glsl() {
  static const std::string source = "#define RELIEF_DIRECTIONS " +
                                    std::to_string(render::relief::kOcclusionDirections) + "\n" +
                                    shaders::relief_lib;
  return source.c_str();
}

}  // namespace impasto::render_gl
