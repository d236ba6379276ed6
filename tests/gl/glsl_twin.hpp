#pragma once
// A GLSL function against its C++ twin in three lines (OpenColorIO's GPU unit tests are the
// model): the harness draws one pixel per input, each calling `call` — a float expression of
// `v`, the case's inputs as a vec4 — after `library`, and compares it with twin(inputs).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl::test {

using TwinInputs = std::array<float, 4>;

// At most 256 inputs (a uniform array of vec4 every GL 3.3 driver holds).
inline void expect_glsl_twin(const std::string& library, const std::string& call,
                             const std::function<double(const TwinInputs&)>& twin,
                             const std::vector<TwinInputs>& inputs, double tolerance) {
  ASSERT_FALSE(inputs.empty());
  ASSERT_LE(inputs.size(), 256u);
  auto context = create_headless_context();
  const int n = static_cast<int>(inputs.size());
  const std::string source = "#version 330 core\n" + library + "\nuniform vec4 inputs[" +
                             std::to_string(n) +
                             "];\nout vec4 result;\nvoid main() {\n"
                             "  vec4 v = inputs[int(gl_FragCoord.x)];\n"
                             "  result = vec4(" +
                             call + ", 0.0, 0.0, 1.0);\n}\n";
  FullscreenPass pass("twin_test.frag", source);
  Framebuffer target(n, 1, TexelFormat::kRGBA32F);
  target.bind();
  pass.program().use();
  std::vector<float> flat;
  for (const TwinInputs& in : inputs) flat.insert(flat.end(), in.begin(), in.end());
  glUniform4fv(pass.program().uniform("inputs"), n, flat.data());
  pass.draw();
  const std::vector<float> pixels = target.read_rgba_float();
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double expected = twin(inputs[static_cast<std::size_t>(i)]);
    const double got = pixels[static_cast<std::size_t>(4 * i)];
    const double error = std::abs(got - expected);
    worst = std::max(worst, error);
    EXPECT_LE(error, tolerance) << call << " at (" << inputs[static_cast<std::size_t>(i)][0] << ", "
                                << inputs[static_cast<std::size_t>(i)][1] << ", "
                                << inputs[static_cast<std::size_t>(i)][2] << ", "
                                << inputs[static_cast<std::size_t>(i)][3] << "): GLSL " << got
                                << ", C++ " << expected;
  }
  std::cout << "[ twin ] " << call << ": " << n << " inputs, largest difference " << worst << "\n";
}

}  // namespace impasto::render_gl::test
