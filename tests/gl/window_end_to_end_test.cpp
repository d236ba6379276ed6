// End to end, under Xvfb: `impasto paint --replay ... --screenshot ... --exit` opens the
// window, replays the bundled demo strokes through the live input path, captures the whole
// window and quits. The screenshot must show the canvas with paint and the panels; the
// session recording must replay to the very same painting as the original strokes.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

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
                                           strokes.string() + "' --json");
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
  // the replay loads in turn with the demo palette (Blue Red Shade first: blue paint).
  const RegionStats canvas = measure(image, {20, 60, 1200 - 360, 760});
  EXPECT_GT(canvas.bright, 20000) << "no white canvas ground";
  EXPECT_GT(canvas.blue, 500) << "no blue where the first strokes were laid";
  EXPECT_GT(canvas.saturated, 2000) << "too little coloured paint";
  EXPECT_GT(canvas.max_luma - canvas.min_luma, 0.5);

  // The session recording replays to exactly the painting of the original strokes.
  ASSERT_TRUE(fs::exists(session));
  EXPECT_EQ(state_hash_of_replay(session), state_hash_of_replay(kDemo));
  fs::remove_all(dir);
}

// `impasto render --gpu` draws a painting through the shaders headless; it must match the CPU
// reference renderer within 2/255 per channel.
// Live mouse input, driven with xdotool: a fast circle sent as one burst of moves with the
// button held, then a release, a move and a press within one burst. Every event must reach
// the session recording as a pen sample with the strokes kept apart.
struct PenLine {
  double time_s, x_mm, y_mm;
  bool tip_down;
};

std::vector<PenLine> pen_lines(const fs::path& recording) {
  std::vector<PenLine> lines;
  std::ifstream in(recording);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind != "pen") continue;
    PenLine pen{};
    double pressure = 0, tilt_x = 0, tilt_y = 0, rotation = 0;
    unsigned buttons = 0;
    fields >> pen.time_s >> pen.x_mm >> pen.y_mm >> pressure >> tilt_x >> tilt_y >> rotation >>
        buttons;
    pen.tip_down = (buttons & 1u) != 0;
    lines.push_back(pen);
  }
  return lines;
}

bool have_xdotool() {
  return std::system("command -v xdotool >/dev/null 2>&1") == 0;
}

void xdotool(const std::string& args) {
  ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << args;
}

TEST(WindowEndToEnd, EveryMouseEventOfAFastCircleAndOfReleaseMovePressIsPainted) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool is not installed";
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_window_mouse_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path session = dir / "session.strokes";
  const pid_t window = fork();
  ASSERT_GE(window, 0);
  if (window == 0) {
    // A recovery folder of its own: the SIGTERM below leaves the session recoverable, and
    // the next run's offer to recover it must not sit where the mouse paints.
    setenv("XDG_STATE_HOME", (dir / "state").c_str(), 1);
    execl(IMPASTO_EXECUTABLE, IMPASTO_EXECUTABLE, "paint", "--record", session.c_str(),
          "--window-width", "1200", "--window-height", "800", static_cast<char*>(nullptr));
    _exit(127);
  }
  // The window is up once it is found and its session has started recording.
  bool up = false;
  for (int i = 0; i < 120 && !up; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    up = std::system("xdotool search --name ' Impasto$' >/dev/null 2>&1") == 0 &&
         fs::exists(session) && fs::file_size(session) > 0;
  }
  ASSERT_TRUE(up) << "the window did not open";
  std::this_thread::sleep_for(std::chrono::seconds(1));  // a few frames: the panels laid out

  // The canvas fills the window left of the panels (x < 820 at this size).
  constexpr int kMoves = 120, kCx = 300, kCy = 400, kR = 150;
  std::string circle =
      "mousemove --sync " + std::to_string(kCx + kR) + " " + std::to_string(kCy) + " mousedown 1";
  for (int i = 1; i <= kMoves; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kMoves;
    circle += " mousemove " + std::to_string(std::lround(kCx + kR * std::cos(a))) + " " +
              std::to_string(std::lround(kCy + kR * std::sin(a)));
  }
  xdotool(circle + " mouseup 1");
  // A stroke down-right, then with the button up a move right, and a second stroke.
  std::string burst = "mousemove --sync 520 200 mousedown 1";
  for (int k = 1; k <= 8; ++k) burst += " mousemove " + std::to_string(520 + 5 * k) + " 200";
  burst += " mouseup 1 mousemove 630 260 mousemove 700 250 mousedown 1";
  for (int k = 1; k <= 11; ++k) burst += " mousemove " + std::to_string(700 + 5 * k) + " 250";
  xdotool(burst + " mouseup 1");
  const std::size_t expected = (1 + kMoves + 1) + (1 + 8 + 1) + (1 + 11 + 1);
  std::vector<PenLine> pens;
  for (int i = 0; i < 80 && pens.size() < expected; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    pens = pen_lines(session);
  }
  kill(window, SIGTERM);
  waitpid(window, nullptr, 0);

  ASSERT_EQ(pens.size(), expected) << "pen samples recorded, one per mouse event";
  std::vector<std::vector<PenLine>> strokes;
  bool open = false;
  for (const PenLine& pen : pens) {
    if (pen.tip_down && !open) strokes.emplace_back();
    if (pen.tip_down || open) strokes.back().push_back(pen);
    open = pen.tip_down;
  }
  ASSERT_EQ(strokes.size(), 3u);
  EXPECT_EQ(strokes[0].size(), 1u + kMoves + 1);
  EXPECT_EQ(strokes[1].size(), 1u + 8 + 1);
  EXPECT_EQ(strokes[2].size(), 1u + 11 + 1);
  for (std::size_t i = 1; i < pens.size(); ++i) EXPECT_GE(pens[i].time_s, pens[i - 1].time_s);

  // The circle is round: the chords between its samples stay within 1 % of its radius
  // (one sample a frame would leave a polygon of a few sides).
  const std::vector<PenLine>& c = strokes[0];
  double cx = 0, cy = 0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) cx += c[i].x_mm, cy += c[i].y_mm;
  cx /= static_cast<double>(c.size() - 2);
  cy /= static_cast<double>(c.size() - 2);
  double r = 0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) r += std::hypot(c[i].x_mm - cx, c[i].y_mm - cy);
  r /= static_cast<double>(c.size() - 2);
  double worst = 0;
  for (std::size_t i = 1; i < c.size(); ++i) {
    const double mx = 0.5 * (c[i].x_mm + c[i - 1].x_mm), my = 0.5 * (c[i].y_mm + c[i - 1].y_mm);
    worst = std::max(worst, std::abs(std::hypot(mx - cx, my - cy) - r));
  }
  EXPECT_LT(worst, 0.01 * r) << "radius " << r << " mm";

  // The second stroke begins where the button went down, far from where the first ended.
  const PenLine& end = strokes[1].back();
  const PenLine& start = strokes[2].front();
  EXPECT_GT(
      std::hypot(start.x_mm - end.x_mm, start.y_mm - end.y_mm),
      0.5 * std::hypot(strokes[1].front().x_mm - end.x_mm, strokes[1].front().y_mm - end.y_mm));
  fs::remove_all(dir);
}

TEST(RenderCommand, GpuOutputMatchesTheCpuOutput) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_render_gpu_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path painting = dir / "demo.impasto";
  const fs::path cpu = dir / "cpu.png", gpu = dir / "gpu.png";
  const std::string impasto = IMPASTO_EXECUTABLE;
  run_and_capture(impasto + " replay '" + kDemo.string() + "' --size 384x256 --save '" +
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

// A wheel click is timed from its X server time to the first frame showing its zoom step:
// `impasto bench window --zoom` sends them and reads the window's own figures back. It
// leaves no session behind to recover.
TEST(WindowEndToEnd, WheelClicksAreTimedToTheirFirstFrames) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool is not installed";
  const fs::path state =
      fs::temp_directory_path() / ("impasto_bench_window_state_" + std::to_string(getpid()));
  fs::remove_all(state);
  std::string text;
  FILE* pipe = popen(("XDG_STATE_HOME=" + state.string() + " " + IMPASTO_EXECUTABLE +
                      " bench window --canvas 256x192 --zoom 2 --zoom-interval 1.5 --json")
                         .c_str(),
                     "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
  ASSERT_EQ(pclose(pipe), 0) << text;
  const nlohmann::json report = nlohmann::json::parse(text);
  const nlohmann::json& canvas = report.at("canvases").at(0);
  // Both clicks, unless the window was still busy with its first frames when it was closed.
  EXPECT_GE(canvas.at("samples").get<int>(), 1);
  EXPECT_LE(canvas.at("samples").get<int>(), 2);
  EXPECT_GT(canvas.at("median_ms").get<double>(), 0.0);
  EXPECT_GE(canvas.at("coarse_frames").get<int>(), 1);  // a zoom step is shown coarsely first
  EXPECT_GE(canvas.at("coarse_factor").get<int>(), 4);
  EXPECT_LE(canvas.at("coarse_factor").get<int>(), 16);
  // The window's recovery folder holds its recording's name at most, no session entry.
  int entries = 0;
  for (const auto& file : fs::exists(state) ? fs::recursive_directory_iterator(state)
                                            : fs::recursive_directory_iterator()) {
    entries += file.path().extension() == ".session" ? 1 : 0;
  }
  EXPECT_EQ(entries, 0) << "a benchmark's window left a session to recover in " << state;
  fs::remove_all(state);
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
