// The optics the surface models and the flakes share, GLSL (optics_lib.glsl) against its C++
// twin (flakes/fresnel.hpp): head on, grazing, total internal reflection and out-of-range
// cosines, which both clamp (not at the critical angle itself, where float and double part).
#include "glsl_twin.hpp"
#include "impasto/flakes/fresnel.hpp"
#include "impasto/render_gl/shader_library.hpp"

namespace impasto::render_gl {
namespace {

std::vector<test::TwinInputs> cosines_and_indices() {
  std::vector<test::TwinInputs> inputs;
  for (float eta : {0.62f, 0.95f, 1.0f, 1.33f, 1.48f, 1.6f, 2.6f})
    for (float c : {-0.1f, 0.0f, 0.01f, 0.2f, 0.5f, 0.8f, 0.99f, 1.0f, 1.1f})
      inputs.push_back({c, eta, 0.0f, 0.0f});
  return inputs;
}

TEST(OpticsGlsl, FresnelDielectricMatchesItsTwin) {
  test::expect_glsl_twin(
      optics_glsl(), "fresnel_dielectric(v.x, v.y)",
      [](const test::TwinInputs& v) { return flakes::fresnel_dielectric(v[0], v[1]); },
      cosines_and_indices(), 2e-6);
}

}  // namespace
}  // namespace impasto::render_gl
