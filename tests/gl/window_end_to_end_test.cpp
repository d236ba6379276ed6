// End to end, under Xvfb: `impasto paint --replay ... --screenshot ... --exit` opens the
// window, replays the bundled demo strokes through the live input path, captures the whole
// window and quits. The screenshot must show the canvas with paint and the panels; the
// session recording must replay to the very same painting as the original strokes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "impasto/render/image.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kDemo = fs::path(IMPASTO_SOURCE_DIR) / "data" / "strokes" / "demo.dat";

std::string run_and_capture(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  EXPECT_EQ(status, 0) << command << "\n" << output;
  return output;
}

std::string state_hash_of_replay(const fs::path& strokes) {
  const std::string json = run_and_capture(std::string(IMPASTO_EXECUTABLE) + " replay '" +
                                           strokes.string() + "' --stats");
  return nlohmann::json::parse(json.substr(json.find('{'))).at("state_hash").get<std::string>();
}

struct Region {
  int x0, y0, x1, y1;
};

struct RegionStats {
  int pixels = 0, bright = 0, blue = 0, saturated = 0;
  double min_luma = 1.0, max_luma = 0.0;
};

RegionStats measure(const impasto::render::Image& image, Region r) {
  RegionStats s;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* p = image.pixel(x, y);
      const double luma = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      const double spread = std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
      ++s.pixels;
      s.bright += luma > 0.8;
      s.blue += p[2] > p[0] + 0.15f && p[2] > p[1];
      s.saturated += spread > 0.2;
      s.min_luma = std::min(s.min_luma, luma);
      s.max_luma = std::max(s.max_luma, luma);
    }
  }
  return s;
}

TEST(WindowEndToEnd, ReplayScreenshotShowsPaintAndPanelsAndRecordsTheSession) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_window_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path screenshot = dir / "window.png";
  const fs::path session = dir / "session.strokes";
  run_and_capture(std::string(IMPASTO_EXECUTABLE) + " paint --replay '" + kDemo.string() +
                  "' --screenshot '" + screenshot.string() + "' --record '" + session.string() +
                  "' --exit --window-width 1200 --window-height 800 2>&1");
  ASSERT_TRUE(fs::exists(screenshot));
  const impasto::render::Image image = impasto::render::read_png(screenshot);
  ASSERT_EQ(image.width, 1200);
  ASSERT_EQ(image.height, 800);

  // The panels: ImGui's dark panels on the right with light text on them.
  const RegionStats panels = measure(image, {1200 - 320, 40, 1200 - 10, 700});
  EXPECT_LT(panels.min_luma, 0.2);
  EXPECT_GT(panels.bright, 200) << "no panel text drawn";

  // The canvas, fitted left of the panels: the white ground and the demo's strokes, which
  // the replay loads in turn with the demo palette (ultramarine first: blue paint).
  const RegionStats canvas = measure(image, {20, 60, 1200 - 360, 760});
  EXPECT_GT(canvas.bright, 20000) << "no white canvas ground";
  EXPECT_GT(canvas.blue, 500) << "no ultramarine where the first strokes were laid";
  EXPECT_GT(canvas.saturated, 2000) << "too little coloured paint";
  EXPECT_GT(canvas.max_luma - canvas.min_luma, 0.5);

  // The session recording replays to exactly the painting of the original strokes.
  ASSERT_TRUE(fs::exists(session));
  EXPECT_EQ(state_hash_of_replay(session), state_hash_of_replay(kDemo));
  fs::remove_all(dir);
}

// `impasto render --gpu` draws a painting through the shaders headless; it must match the CPU
// reference renderer within 2/255 per channel.
TEST(RenderCommand, GpuOutputMatchesTheCpuOutput) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_render_gpu_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path painting = dir / "demo.impasto";
  const fs::path cpu = dir / "cpu.png", gpu = dir / "gpu.png";
  const std::string impasto = IMPASTO_EXECUTABLE;
  run_and_capture(impasto + " replay '" + kDemo.string() + "' --size 384x256 --out '" +
                  painting.string() + "' 2>&1");
  const std::string light = " --light A --wavelengths 6 --light-dir 200,40";
  run_and_capture(impasto + " render '" + painting.string() + "' --out '" + cpu.string() + "'" +
                  light + " 2>&1");
  run_and_capture(impasto + " render '" + painting.string() + "' --gpu --out '" + gpu.string() +
                  "'" + light + " 2>&1");
  const impasto::render::Image a = impasto::render::read_png(cpu);
  const impasto::render::Image b = impasto::render::read_png(gpu);
  ASSERT_EQ(a.width, 384);
  ASSERT_EQ(a.height, 256);
  ASSERT_EQ(b.width, a.width);
  ASSERT_EQ(b.height, a.height);
  double max_difference = 0.0, sum = 0.0, max_contrast = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = std::abs(static_cast<double>(a.rgb[i]) - b.rgb[i]);
    max_difference = std::max(max_difference, d);
    sum += d;
    max_contrast = std::max(max_contrast, std::abs(static_cast<double>(a.rgb[i]) - a.rgb[i % 3]));
  }
  const double mean = sum / static_cast<double>(a.rgb.size());
  std::cout << "render --gpu vs CPU: max " << max_difference * 255 << "/255, mean " << mean * 255
            << "/255\n";
  EXPECT_GT(max_contrast, 0.2) << "the painting has no paint to compare";
  EXPECT_LE(max_difference, 2.0 / 255.0 + 1e-6);
  fs::remove_all(dir);
}

TEST(RenderCommand, GpuWithAMissingPaintingIsAClearError) {
  std::string text;
  FILE* pipe = popen((std::string(IMPASTO_EXECUTABLE) +
                      " render /nonexistent/painting.impasto --gpu --out x.png 2>&1")
                         .c_str(),
                     "r");
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
  EXPECT_NE(pipe ? pclose(pipe) : 0, 0);
  EXPECT_NE(text.find("painting.impasto"), std::string::npos) << text;
}

TEST(WindowEndToEnd, MissingStrokeFileIsAClearError) {
  const std::string output = [] {
    std::string text;
    FILE* pipe = popen(
        (std::string(IMPASTO_EXECUTABLE) + " paint --replay /nonexistent/strokes.dat --exit 2>&1")
            .c_str(),
        "r");
    char buffer[4096];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    EXPECT_NE(pipe ? pclose(pipe) : 0, 0);
    return text;
  }();
  EXPECT_NE(output.find("strokes.dat"), std::string::npos) << output;
}

}  // namespace
