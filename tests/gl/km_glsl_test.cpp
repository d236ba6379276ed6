// The GLSL ports of the per-cell K-M and shading maths against the CPU reference functions
// (render/kubelka_munk_cell.hpp, render/shading.hpp) and against their analytic limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "impasto/render/kubelka_munk_cell.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/shader_library.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {
namespace {

namespace km = render::km;
namespace shade = render::shade;

constexpr int kKmGridSide = 32;  // a 32x32 grid of test cases, one per pixel

// Inputs of case (x, y): spans of many decades, with exact zeros in the first row/column.
float absorption_of(int x) {
  return x == 0 ? 0.0f : 1e-4f * std::pow(1.6f, float(x));
}
float scattering_of(int y) {
  return y == 0 ? 0.0f : 1e-4f * std::pow(1.6f, float(y));
}
float thickness_of(int x, int y) {
  return ((x * 7 + y * 3) % 11 == 0) ? 0.0f : 0.02f * float((x * 5 + y * 13) % 40);
}
float below_of(int x, int y) {
  return float((x * 3 + y * 5) % 17) / 16.0f;
}

// Runs `body` (a fragment shader main writing `result`) over the kKmGridSide x kKmGridSide grid.
// The case inputs travel as uniforms (K per column, S per row) and an RG32F texture (thickness,
// reflectance below), so both sides compute from bit-identical inputs.
std::vector<float> run_pass(const std::string& body) {
  const std::string source = std::string("#version 330 core\n") + km_glsl() + shading_glsl() +
                             "uniform float absorption[32];\nuniform float scattering[32];\n"
                             "uniform sampler2D thickness_below;\nout vec4 result;\n" +
                             body;
  Framebuffer target(kKmGridSide, kKmGridSide, TexelFormat::kRGBA32F);
  FullscreenPass pass("test.frag", source);
  std::vector<float> absorption(kKmGridSide), scattering(kKmGridSide),
      thickness_below(2 * kKmGridSide * kKmGridSide);
  for (int i = 0; i < kKmGridSide; ++i) {
    absorption[i] = absorption_of(i);
    scattering[i] = scattering_of(i);
  }
  for (int y = 0; y < kKmGridSide; ++y) {
    for (int x = 0; x < kKmGridSide; ++x) {
      thickness_below[2 * (y * kKmGridSide + x)] = thickness_of(x, y);
      thickness_below[2 * (y * kKmGridSide + x) + 1] = below_of(x, y);
    }
  }
  Texture inputs(kKmGridSide, kKmGridSide, 0, TexelFormat::kRG32F);
  inputs.upload(0, 0, kKmGridSide, kKmGridSide, 0, thickness_below.data(), kKmGridSide);
  target.bind();
  pass.program().use();
  inputs.bind(0);
  glUniform1i(pass.program().uniform("thickness_below"), 0);
  glUniform1fv(pass.program().uniform("absorption"), kKmGridSide, absorption.data());
  glUniform1fv(pass.program().uniform("scattering"), kKmGridSide, scattering.data());
  pass.draw();
  return target.read_rgba_float();
}

class KmGlsl : public ::testing::Test {
 protected:
  void SetUp() override { context_ = create_headless_context(); }
  std::unique_ptr<GlContext> context_;
};

TEST_F(KmGlsl, LayerAndCompositeMatchTheCpuReference) {
  const auto pixels = run_pass(R"glsl(
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 d_below = texelFetch(thickness_below, p, 0).rg;
  vec2 rt = km_layer(absorption[p.x], scattering[p.y], d_below.x);
  result = vec4(rt, km_composite(rt, d_below.y), absorption[p.x]);
})glsl");
  double worst = 0.0;
  for (int y = 0; y < kKmGridSide; ++y) {
    for (int x = 0; x < kKmGridSide; ++x) {
      const float* p = &pixels[(y * kKmGridSide + x) * 4];
      const float K = absorption_of(x);
      ASSERT_EQ(p[3], K);  // the inputs arrived unchanged
      const km::LayerRT cpu = km::layer(K, scattering_of(y), thickness_of(x, y));
      const float composite = km::composite(cpu, below_of(x, y));
      // exp on the GPU is within a few ulp of std::exp: differences stay near 1e-6.
      EXPECT_NEAR(p[0], cpu.reflectance, 4e-6f) << "K " << K << " S " << scattering_of(y);
      EXPECT_NEAR(p[1], cpu.transmittance, 4e-6f) << "K " << K << " S " << scattering_of(y);
      EXPECT_NEAR(p[2], composite, 4e-6f);
      worst = std::max({worst, std::abs(double(p[0]) - cpu.reflectance),
                        std::abs(double(p[1]) - cpu.transmittance),
                        std::abs(double(p[2]) - composite)});
    }
  }
  RecordProperty("max_abs_difference", std::to_string(worst));
}

TEST_F(KmGlsl, LayerLimitsAreExactOnTheGpu) {
  // Pure absorber: R = 0, T = e^(-Kd). Pure scatterer: R = Sd/(1+Sd), T = 1/(1+Sd).
  // Zero thickness: R = 0, T = 1. Very thick: R = S/(K+S+sqrt(K(K+2S))), T = 0, no NaN.
  const auto pixels = run_pass(R"glsl(
void main() {
  int x = int(gl_FragCoord.x);
  vec2 rt;
  if (x == 0) rt = km_layer(2.0, 0.0, 0.7);
  else if (x == 1) rt = km_layer(0.0, 3.0, 0.5);
  else if (x == 2) rt = km_layer(5.0, 7.0, 0.0);
  else if (x == 3) rt = km_layer(0.5, 2.0, 1e6);
  else rt = km_layer(1e30, 1e30, 1e30);
  result = vec4(rt, 0.0, 1.0);
})glsl");
  auto at = [&](int x, int c) { return pixels[x * 4 + c]; };
  EXPECT_FLOAT_EQ(at(0, 0), 0.0f);
  EXPECT_NEAR(at(0, 1), std::exp(-1.4f), 1e-6f);
  EXPECT_NEAR(at(1, 0), 1.5f / 2.5f, 1e-6f);
  EXPECT_NEAR(at(1, 1), 1.0f / 2.5f, 1e-6f);
  EXPECT_FLOAT_EQ(at(2, 0), 0.0f);
  EXPECT_FLOAT_EQ(at(2, 1), 1.0f);
  EXPECT_NEAR(at(3, 0), km::reflectance_infinite(0.5f, 2.0f), 1e-6f);
  EXPECT_FLOAT_EQ(at(3, 1), 0.0f);
  EXPECT_TRUE(std::isfinite(at(4, 0)) && std::isfinite(at(4, 1)));
}

TEST_F(KmGlsl, ShadingMatchesTheCpuReference) {
  // Heights and light from the pixel: the four neighbour heights on a slope field, the light
  // sweeping azimuth and elevation.
  const auto pixels = run_pass(R"glsl(
void main() {
  int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
  float left = 0.01 * float(x % 7), right = 0.013 * float(y % 5), up = 0.02 * float((x + y) % 3), down = 0.0;
  vec3 n = shade_height_normal(left, right, up, down, 0.085);
  float azimuth = 0.2 * float(x), elevation = 0.05 + 0.045 * float(y);
  vec3 l = vec3(cos(elevation) * cos(azimuth), cos(elevation) * sin(azimuth), sin(elevation));
  vec2 m = shade_blend(vec2(0.04, 12.0), vec2(0.35, 80.0), float(x - 8) / 16.0);
  result = vec4(shade_blinn_phong(n, l, 0.25, m, vec2(1.0), 0.03), l.x, l.z);
})glsl");
  double worst = 0.0;
  for (int y = 0; y < kKmGridSide; ++y) {
    for (int x = 0; x < kKmGridSide; ++x) {
      const float* p = &pixels[(y * kKmGridSide + x) * 4];
      const shade::Vec3 n = shade::height_normal(0.01f * float(x % 7), 0.013f * float(y % 5),
                                                 0.02f * float((x + y) % 3), 0.0f, 0.085f);
      const shade::Vec3 l = shade::light_direction(0.2f * float(x), 0.05f + 0.045f * float(y));
      ASSERT_NEAR(p[2], l.x, 2e-6f);
      ASSERT_NEAR(p[3], l.z, 2e-6f);
      const shade::Material m = shade::blend({0.04f, 12.0f}, {0.35f, 80.0f}, float(x - 8) / 16.0f);
      const shade::Shading cpu = shade::blinn_phong(n, l, 0.25f, m, {}, 0.03f);
      EXPECT_NEAR(p[0], cpu.diffuse, 1e-5f * std::max(1.0f, cpu.diffuse)) << x << "," << y;
      EXPECT_NEAR(p[1], cpu.specular, 1e-5f) << x << "," << y;
      worst = std::max(
          {worst, std::abs(double(p[0]) - cpu.diffuse), std::abs(double(p[1]) - cpu.specular)});
    }
  }
  RecordProperty("max_abs_difference", std::to_string(worst));
}

}  // namespace
}  // namespace impasto::render_gl
