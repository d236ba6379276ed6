// Headless OpenGL: a context, a render target, a shader, texture updates, read-back.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {
namespace {

// A gradient known in closed form: red = (x + 0.5) / width, green = (y + 0.5) / height.
constexpr const char* kGradientShader = R"glsl(#version 330 core
uniform vec2 size;
out vec4 color;
void main() { color = vec4(gl_FragCoord.xy / size, 0.25, 1.0); }
)glsl";

// Copies texel (x, y) of an R32F texture into red, doubled (so the shader did something).
constexpr const char* kFetchShader = R"glsl(#version 330 core
uniform sampler2D grid;
out vec4 color;
void main() { color = vec4(2.0 * texelFetch(grid, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0); }
)glsl";

TEST(GlContext, RendersAnAnalyticGradientAndReadsItBack) {
  auto context = create_headless_context();
  const int width = 64, height = 32;
  Framebuffer target(width, height, TexelFormat::kRGBA32F);
  FullscreenPass pass("gradient.frag", kGradientShader);
  target.bind();
  pass.program().use();
  glUniform2f(pass.program().uniform("size"), width, height);
  pass.draw();
  check_gl_error("gradient pass");
  const std::vector<float> pixels = target.read_rgba_float();
  ASSERT_EQ(pixels.size(), size_t{width * height * 4});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float* p = &pixels[(static_cast<size_t>(y) * width + x) * 4];
      EXPECT_NEAR(p[0], (x + 0.5f) / width, 1e-6f) << x << "," << y;
      EXPECT_NEAR(p[1], (y + 0.5f) / height, 1e-6f) << x << "," << y;
      EXPECT_FLOAT_EQ(p[2], 0.25f);
      EXPECT_FLOAT_EQ(p[3], 1.0f);
    }
  }
}

TEST(GlContext, RgbaEightBitTargetRoundsToNearest) {
  auto context = create_headless_context();
  Framebuffer target(16, 4, TexelFormat::kRGBA8);
  FullscreenPass pass("gradient.frag", kGradientShader);
  target.bind();
  pass.program().use();
  glUniform2f(pass.program().uniform("size"), 16, 4);
  pass.draw();
  const auto pixels = target.read_rgba8();
  for (int x = 0; x < 16; ++x) {
    EXPECT_NEAR(pixels[x * 4], std::lround((x + 0.5) / 16 * 255), 1) << x;
    EXPECT_NEAR(pixels[x * 4 + 2], 64, 1);
  }
}

TEST(GlContext, TileUploadChangesOnlyItsRegion) {
  auto context = create_headless_context();
  const int size = 32, tile = 8;
  Texture grid(size, size, 0, TexelFormat::kR32F);
  std::vector<float> zeros(size * size, 0.0f);
  grid.upload(0, 0, size, size, 0, zeros.data(), size);
  // A tile taken from the middle of a wider source grid (row stride 20 texels).
  std::vector<float> source(20 * tile);
  for (int i = 0; i < static_cast<int>(source.size()); ++i) source[i] = 0.01f * i;
  grid.upload(16, 8, tile, tile, 0, source.data(), 20);

  Framebuffer target(size, size, TexelFormat::kRGBA32F);
  FullscreenPass pass("fetch.frag", kFetchShader);
  target.bind();
  pass.program().use();
  grid.bind(0);
  glUniform1i(pass.program().uniform("grid"), 0);
  pass.draw();
  const auto pixels = target.read_rgba_float();
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const bool inside = x >= 16 && x < 16 + tile && y >= 8 && y < 8 + tile;
      const float expected = inside ? 2.0f * source[(y - 8) * 20 + (x - 16)] : 0.0f;
      EXPECT_FLOAT_EQ(pixels[(y * size + x) * 4], expected) << x << "," << y;
    }
  }
}

TEST(GlContext, UploadOutsideTheTextureThrows) {
  auto context = create_headless_context();
  Texture grid(8, 8, 2, TexelFormat::kRGBA32F);
  std::vector<float> texels(4 * 4 * 4);
  EXPECT_THROW(grid.upload(6, 0, 4, 4, 0, texels.data(), 4), std::out_of_range);
  EXPECT_THROW(grid.upload(0, 0, 4, 4, 2, texels.data(), 4), std::out_of_range);
  EXPECT_NO_THROW(grid.upload(4, 4, 4, 4, 1, texels.data(), 4));
}

TEST(GlContext, AbsurdTextureSizeIsAClearError) {
  auto context = create_headless_context();
  try {
    Texture grid(1 << 20, 4, 0, TexelFormat::kR32F);
    FAIL() << "a 2^20-wide texture was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("1048576x4"), std::string::npos) << e.what();
  }
}

TEST(GlContext, CompileErrorNamesTheShaderAndCarriesTheLog) {
  auto context = create_headless_context();
  try {
    FullscreenPass pass("broken.frag", "#version 330 core\nout vec4 c;\nvoid main() { c = nope; }");
    FAIL() << "a broken shader compiled";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("broken.frag"), std::string::npos) << message;
    EXPECT_NE(message.find("nope"), std::string::npos) << message;
  }
}

TEST(GlContext, OsMesaFallbackRendersTheSameGradient) {
  std::unique_ptr<GlContext> context;
  try {
    context = create_headless_context(HeadlessBackend::kOsMesa);
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << e.what();
  }
  EXPECT_EQ(context->backend_name(), "osmesa");
  Framebuffer target(8, 8, TexelFormat::kRGBA32F);
  FullscreenPass pass("gradient.frag", kGradientShader);
  target.bind();
  pass.program().use();
  glUniform2f(pass.program().uniform("size"), 8, 8);
  pass.draw();
  const auto pixels = target.read_rgba_float();
  EXPECT_NEAR(pixels[(3 * 8 + 5) * 4 + 0], 5.5f / 8, 1e-6f);
  EXPECT_NEAR(pixels[(3 * 8 + 5) * 4 + 1], 3.5f / 8, 1e-6f);
}

}  // namespace
}  // namespace impasto::render_gl
