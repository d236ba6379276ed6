// The close-up of cracks in GLSL (render/gl/shaders/crack_close_up_lib.glsl) against the CPU
// reference (render/crack_close_up.hpp): every pixel of a magnified cell, every shape, under
// an overhead and a low light and an oblique view, within 2/255.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impasto/render/crack_close_up.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl {
namespace {

constexpr int kP = 32;           // pixels per cell
constexpr double kCellMm = 1.0;  // the cell's side

std::string library_source() {
  std::ifstream in(std::string(IMPASTO_SOURCE_DIR) + "/render/gl/shaders/crack_close_up_lib.glsl");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const char* const kMain = R"glsl(
uniform int shape;
uniform float L, R, cell_mm;
uniform int P;
uniform vec3 eye;
uniform vec3 suns[CLOSE_UP_MAX_RAYS];
uniform int rays;
uniform float e_sky, e_sun, G;
uniform vec4 rho0, surface;
out vec4 result;
void main() {
  vec2 px = floor(gl_FragCoord.xy);
  float pixel_mm = cell_mm / float(P);
  vec3 o = vec3((px + 0.5) * pixel_mm - 0.5 * cell_mm, 0.0);
  vec4 v = close_up_pixel(shape, L, R, o, eye, suns, rays, e_sky, e_sun, G, rho0);
  result = v.x < 0.0 ? surface : v;
}
)glsl";

// Both sides for one cell; returns the largest difference.
double compare(const FullscreenPass& pass, const paintcore::CrackRecord& record,
               const render::CloseUpLight& light, const render::CloseUpView& view) {
  const std::vector<float> surface = {0.7f, 0.5f, 0.3f, 0.9f};
  const std::vector<float> wall = {0.8f, 0.2f, 0.5f, 0.95f};
  std::vector<float> cpu(static_cast<std::size_t>(kP * kP * 4));
  render::crack_close_up_cell(record, kCellMm, false, kP, surface, wall, light, view, cpu);

  const double G = render::crack_optics(record, kCellMm).G;
  const double sun_z = light.toward_light.z;
  const double e_sky = sun_z > 0.0 ? light.sky_fraction : 1.0;
  const double e_sun = sun_z > 0.0 ? (1.0 - light.sky_fraction) / sun_z : 0.0;
  std::vector<float> suns;
  for (const auto& s : render::close_up_light_directions(light)) {
    for (double c : {s.x, s.y, s.z}) suns.push_back(static_cast<float>(c));
  }

  Framebuffer target(kP, kP, TexelFormat::kRGBA32F);
  target.bind();
  const ShaderProgram& program = pass.program();
  program.use();
  glUniform1i(program.uniform("shape"), record.shape);
  glUniform1f(program.uniform("L"), record.depth_mm);
  glUniform1f(program.uniform("R"), record.half_width_mm);
  glUniform1f(program.uniform("cell_mm"), static_cast<float>(kCellMm));
  glUniform1i(program.uniform("P"), kP);
  glUniform3f(program.uniform("eye"), static_cast<float>(view.toward_eye.x),
              static_cast<float>(view.toward_eye.y), static_cast<float>(view.toward_eye.z));
  glUniform3fv(program.uniform("suns"), light.shadow_rays, suns.data());
  glUniform1i(program.uniform("rays"), light.shadow_rays);
  glUniform1f(program.uniform("e_sky"), static_cast<float>(e_sky));
  glUniform1f(program.uniform("e_sun"), static_cast<float>(e_sun));
  glUniform1f(program.uniform("G"), static_cast<float>(G));
  glUniform4fv(program.uniform("rho0"), 1, wall.data());
  glUniform4fv(program.uniform("surface"), 1, surface.data());
  pass.draw();
  const std::vector<float> gpu = target.read_rgba_float();  // row 0: py = 0, as the CPU
  double worst = 0.0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    worst = std::max(worst, std::abs(double(gpu[i]) - double(cpu[i])));
  }
  return worst;
}

class CrackCloseUpGlsl : public ::testing::Test {
 protected:
  void SetUp() override { context_ = create_headless_context(); }
  std::unique_ptr<GlContext> context_;
};

TEST_F(CrackCloseUpGlsl, MatchesTheCpuReference) {
  const FullscreenPass pass("crack_close_up_test.frag",
                            "#version 330 core\n" + library_source() + kMain);
  const double low = 30.0 * 3.14159265358979 / 180.0;
  const std::vector<render::CloseUpLight> lights = {
      render::CloseUpLight{},
      render::CloseUpLight{{std::cos(low), 0.0, std::sin(low)}, 0.1, 0.2, 16}};
  const std::vector<render::CloseUpView> views = {
      render::CloseUpView{}, render::CloseUpView{{std::sin(0.4), 0.0, std::cos(0.4)}}};
  double worst = 0.0;
  for (std::uint8_t shape = 0; shape < paintcore::kCrackShapeCount; ++shape) {
    for (float depth : {0.1f, 0.6f}) {
      paintcore::CrackRecord record;
      record.depth_mm = depth;
      record.half_width_mm = 0.3f;
      record.shape = shape;
      for (const auto& light : lights) {
        for (const auto& view : views) {
          const double d = compare(pass, record, light, view);
          worst = std::max(worst, d);
          EXPECT_LE(d, 2.0 / 255.0) << "shape " << int(shape) << " depth " << depth;
        }
      }
    }
  }
  std::printf("close-up GLSL vs CPU: worst |difference| %.2e (%.3f/255)\n", worst, worst * 255);
}

}  // namespace
}  // namespace impasto::render_gl
