// The window's everyday tools end to end, under Xvfb, driven by real X input (xdotool): the
// eyedropper picks the paint of a stroke and loads the brush with it, Ctrl+S saves the
// painting (with that brush), a brush preset saved in the window is read back by the next
// window and applied, the brush's outline follows the pointer over the canvas, a stroke
// with an empty brush says so, and the tool bar's paint chips load the brush.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"
#include "window_driver.hpp"

namespace {

using namespace impasto::window_test;

const std::string kRed = "Red";
const std::string kGreen = "Green";

// A painting of two strokes, red above green, on a 600 x 400 cell canvas at 150 dpi.
fs::path two_stroke_painting(const fs::path& dir) {
  const fs::path strokes = dir / "two.strokes";
  std::ofstream out(strokes);
  out << "impasto-strokes 2\ncanvas 600 400 150\nbrush round size=10 stiffness=0.5\n";
  double t = 0.0;
  for (const auto& [pigment, y] : {std::pair{kRed, 20.0}, std::pair{kGreen, 48.0}}) {
    out << "wipe\nload 300 \"" << pigment << "\" 1\n";
    for (int i = 0; i <= 70; ++i, t += 0.02)
      out << "pen " << t << " " << 15.0 + i << " " << y << " " << (i < 70 ? 0.8 : 0.0) << " 0 0 0 "
          << (i < 70 ? 17 : 16) << "\n";
  }
  out.close();
  const fs::path painting = dir / "two.impasto";
  int status = -1;
  const std::string output =
      run_output(std::string(IMPASTO_EXECUTABLE) + " replay '" + strokes.string() + "' --save '" +
                     painting.string() + "'",
                 &status);
  EXPECT_EQ(status, 0) << output;
  return painting;
}

struct Centroid {
  int x = 0, y = 0, pixels = 0;
};

// Where the red stroke is on screen: the centroid of clearly red pixels left of the panels.
Centroid red_centroid(const impasto::render::Image& image) {
  long sx = 0, sy = 0;
  Centroid c;
  for (int y = 60; y < image.height - 40; ++y) {
    for (int x = 0; x < image.width - 360; ++x) {
      const float* p = image.pixel(x, y);
      if (p[0] > 0.45f && p[1] < 0.25f && p[2] < 0.25f) {
        sx += x;
        sy += y;
        ++c.pixels;
      }
    }
  }
  if (c.pixels > 0) {
    c.x = static_cast<int>(sx / c.pixels);
    c.y = static_cast<int>(sy / c.pixels);
  }
  return c;
}

TEST(WindowTools, EyedropperLoadsTheBrushWithThePickedPaintAndCtrlSSavesIt) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_eyedropper");
  const fs::path painting = two_stroke_painting(dir);
  const fs::path recording = dir / "session.strokes";
  const auto saved_at = fs::last_write_time(painting);
  {
    Window window(dir, recording, {painting.string()});
    ASSERT_TRUE(window.up()) << "the window did not open";
    Centroid red;
    ASSERT_TRUE(wait_for([&] {
      red = red_centroid(window.screenshot(dir / "window.png"));
      return red.pixels > 500;
    })) << "no red stroke on screen";

    // I, then a click on the red stroke: the brush is wiped and loaded with red alone.
    window.move(red.x, red.y);
    window.key("i");
    window.click(red.x, red.y);
    std::vector<std::string> loads;
    ASSERT_TRUE(wait_for([&] {
      loads = lines_starting(recording, "load ");
      return !loads.empty();
    })) << read_text(recording);
    ASSERT_EQ(loads.size(), 1u) << read_text(recording);
    EXPECT_NE(loads[0].find('"' + kRed + '"'), std::string::npos) << loads[0];
    EXPECT_EQ(loads[0].find(kGreen), std::string::npos) << loads[0];
    EXPECT_EQ(lines_starting(recording, "wipe").size(), 1u);

    // Ctrl+S: the painting's own file is written again, now with that brush.
    window.key("ctrl+s");
    ASSERT_TRUE(wait_for([&] {
      std::error_code error;
      return fs::last_write_time(painting, error) != saved_at && !error &&
             !lines_starting(recording, "saved ").empty();
    })) << "Ctrl+S did not save "
        << painting;
  }
  const impasto::paintcore::Painting saved = impasto::paintcore::Painting::load(painting);
  const impasto::paintcore::PaintTotals brush = saved.brush_totals();
  EXPECT_GT(brush.volume, 1.0);
  const auto& slots = saved.pigment_slots();
  for (std::size_t s = 0; s < slots.size(); ++s) {
    if (slots[s] == kRed) {
      EXPECT_GT(brush.pigment[s], 0.99 * brush.volume) << "the brush holds red";
    } else {
      EXPECT_LT(brush.pigment[s], 0.01 * brush.volume) << slots[s] << " on the brush";
    }
  }
  fs::remove_all(dir);
}

// key = value lines of a preset file.
std::map<std::string, std::string> preset_fields(const fs::path& file) {
  std::map<std::string, std::string> fields;
  std::istringstream in(read_text(file));
  std::string line;
  while (std::getline(in, line)) {
    const auto equals = line.find('=');
    if (line.empty() || line[0] == '#' || equals == std::string::npos) continue;
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(' '));
      s.erase(s.find_last_not_of(' ') + 1);
      return s;
    };
    fields[trim(line.substr(0, equals))] = trim(line.substr(equals + 1));
  }
  return fields;
}

// Whether a modal window's title bar (ImGui's dark style, TitleBgActive) is in the middle of
// the window.
bool modal_shown(const impasto::render::Image& image) {
  int title = 0;
  for (int y = image.height / 4; y < image.height * 3 / 4; ++y)
    for (int x = image.width / 4; x < image.width * 3 / 4; ++x) {
      const float* p = image.pixel(x, y);
      title += std::abs(p[0] - 0.16f) < 0.03f && std::abs(p[1] - 0.29f) < 0.03f &&
               std::abs(p[2] - 0.48f) < 0.03f;
    }
  return title > 2000;
}

// The Edit menu at the default ImGui style (13 px font: a menu row is 17 px high).
constexpr int kEditMenuX = 69, kMenuBarY = 10;
constexpr int kSavePresetRowY = 177;
// The tool bar in a 1000 px wide window: the user's preset follows the eight shipped ones, at
// the end of the second row.
constexpr int kBigKnifeButtonX = 438, kBigKnifeButtonY = 66;

TEST(WindowTools, APresetSavedInTheWindowIsReadBackByTheNextWindowAndApplied) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_presets");
  const fs::path preset = dir / "config" / "impasto" / "presets" / "big-knife.preset";
  std::string knife_brush;
  {
    const fs::path recording = dir / "first.strokes";
    Window window(dir, recording, {});
    ASSERT_TRUE(window.up()) << "the window did not open";
    // Three steps larger, and the knife: 6 mm x 1.25^3.
    window.move(400, 400);
    window.key("bracketright bracketright bracketright k");
    ASSERT_TRUE(wait_for([&] {
      const auto brushes = lines_starting(recording, "brush knife size=11.71875 ");
      if (!brushes.empty()) knife_brush = brushes.back();
      return !brushes.empty();
    })) << read_text(recording);
    // Edit > Save brush as preset..., typed into its name field: the letters typed (b, i, k)
    // must not act as the brush, eyedropper and knife keys meanwhile.
    // (Tried again if a click was lost: typing only once the prompt is seen.)
    bool prompt = false;
    for (int attempt = 0; attempt < 4 && !prompt; ++attempt) {
      window.key("Escape");
      window.click(kEditMenuX, kMenuBarY);
      window.click(kEditMenuX + 40, kSavePresetRowY);
      prompt = wait_for([&] { return modal_shown(window.screenshot(dir / "prompt.png")); }, 5s);
    }
    ASSERT_TRUE(prompt) << "the Save brush preset prompt did not open";
    window.type("Big knife");
    window.key("Return");
    const bool saved = wait_for([&] { return fs::exists(preset); });
    if (!saved) window.screenshot(dir / "no-preset.png");
    ASSERT_TRUE(saved) << "no " << preset << " (the window: " << dir / "no-preset.png"
                       << ")";
    const auto fields = preset_fields(preset);
    EXPECT_EQ(fields.at("name"), "Big knife");
    EXPECT_EQ(fields.at("head"), "knife");
    EXPECT_EQ(fields.at("size_mm"), "11.71875");
    EXPECT_EQ(fields.at("stiffness"), "0.5");
    EXPECT_EQ(fields.at("body"), "heavy");
    // Back to the round brush, a step smaller: the preset is no longer the brush.
    window.move(400, 400);
    window.key("b bracketleft");
    ASSERT_TRUE(wait_for([&] {
      return !lines_starting(recording, "brush round size=9.375 ").empty();
    })) << read_text(recording);
  }
  // A new window reads the user's presets; its "Big knife" button gives the same brush again.
  const fs::path recording = dir / "second.strokes";
  Window window(dir, recording, {}, "second-state");
  ASSERT_TRUE(window.up()) << "the second window did not open";
  const std::size_t brushes_before = lines_starting(recording, "brush ").size();
  std::vector<std::string> brushes;
  bool applied = false;
  for (int attempt = 0; attempt < 4 && !applied; ++attempt) {
    window.click(kBigKnifeButtonX, kBigKnifeButtonY);
    applied = wait_for(
        [&] {
          brushes = lines_starting(recording, "brush ");
          return brushes.size() > brushes_before;
        },
        5s);
  }
  ASSERT_TRUE(applied) << read_text(recording);
  EXPECT_EQ(brushes.back(), knife_brush);
  fs::remove_all(dir);
}

// The brush on the canvas: its outline follows the pointer over the canvas (a ring of the
// round head's size around it, nothing elsewhere), and goes when the pointer is over a panel.
TEST(WindowTools, TheBrushOutlineFollowsThePointerOverTheCanvas) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_outline");
  Window window(dir, dir / "outline.strokes", {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  // Dark pixels on the bare (near-white) canvas: near the point, and anywhere else on it.
  const auto dark_pixels = [&](int px, int py, int& near, int& elsewhere) {
    const impasto::render::Image s = window.screenshot();
    near = elsewhere = 0;
    if (s.width != 1000 || s.height != 700) return false;
    for (int y = 135; y < 565; ++y) {
      for (int x = 30; x < 610; ++x) {
        const float* p = s.pixel(x, y);
        if (p[0] + p[1] + p[2] > 1.2f) continue;
        (std::hypot(x - px, y - py) < 25.0 ? near : elsewhere) += 1;
      }
    }
    return true;
  };
  int near = 0, elsewhere = 0;
  for (const auto& [x, y] : {std::pair{300, 350}, std::pair{450, 250}}) {
    window.move(x - 6, y - 3);
    window.move(x, y);
    // (Until the canvas is shown, the window's background is dark everywhere.)
    EXPECT_TRUE(wait_for([&] {
      return dark_pixels(x, y, near, elsewhere) && near > 20 && near < 600 && elsewhere == 0;
    })) << "no ring around the pointer at "
        << x << "," << y << " alone (" << near << " dark pixels within 25 px, " << elsewhere
        << " elsewhere)";
  }
  window.move(800, 300);  // over the palette panel
  EXPECT_TRUE(wait_for([&] { return dark_pixels(450, 250, near, elsewhere) && near == 0; }))
      << "the outline stayed on the canvas with the pointer over a panel";
  EXPECT_EQ(elsewhere, 0);
  fs::remove_all(dir);
}

// A stroke with nothing on the brush paints nothing: the window says so beside the pointer,
// once (a second stroke gets no note).
TEST(WindowTools, AStrokeWithAnEmptyBrushSaysSoOnce) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_empty_brush");
  Window window(dir, dir / "empty.strokes", {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  // The note's yellow text, below and right of the pointer at y = 300, x up to 400, over the
  // canvas (the Palette panel's Cold Yellow chips are yellow too, right of x = 680).
  const auto note_pixels = [&] {
    const impasto::render::Image s = window.screenshot();
    int yellow = 0;
    if (s.width != 1000 || s.height != 700) return 0;
    for (int y = 305; y < 345; ++y) {
      for (int x = 200; x < 620; ++x) {
        const float* p = s.pixel(x, y);
        if (p[0] > 0.8f && p[1] > 0.6f && p[2] < 0.6f) ++yellow;
      }
    }
    return yellow;
  };
  EXPECT_EQ(note_pixels(), 0);
  window.scrub(200, 400, 300);
  EXPECT_TRUE(wait_for([&] { return note_pixels() > 50; })) << "no note about the empty brush";
  EXPECT_TRUE(wait_for([&] { return note_pixels() == 0; }, std::chrono::seconds(15)))
      << "the note stayed";
  window.scrub(200, 400, 300);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(note_pixels(), 0) << "told twice";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  fs::remove_all(dir);
}

// A wheel notch over the canvas zooms by a quarter about the pointer: the canvas, measured on
// screen across its middle row, is 1.25 times narrower after a notch down.
TEST(WindowTools, AWheelNotchZoomsByAQuarter) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_wheel");
  Window window(dir, dir / "wheel.strokes", {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  // The canvas's light pixels along row 350, left of the panels (x < 660).
  const auto canvas_width = [&] {
    const impasto::render::Image s = window.screenshot();
    if (s.width != 1000) return 0;
    int first = -1, last = -1;
    for (int x = 0; x < 660; ++x) {
      const float* p = s.pixel(x, 350);
      if (p[0] > 0.6f && p[1] > 0.6f && p[2] > 0.6f) {
        if (first < 0) first = x;
        last = x;
      }
    }
    return first < 0 ? 0 : last - first + 1;
  };
  // The view settled: shaded whole, or refined from a motion's coarse frame (blocks of up to
  // 16 pixels on a loaded machine, which blur the canvas's edge and go on a few blocks a frame
  // for seconds, each frame slow where other programs share the cores). Settled when three
  // captures a second apart show the same canvas area, pixel for pixel; measured before the
  // notch as after it.
  const auto canvas_area = [&] {  // left of the panels, between the tool bar and status bar
    const impasto::render::Image s = window.screenshot();
    std::vector<float> area;
    if (s.width != 1000) return area;
    for (int y = 120; y < 650; ++y) area.insert(area.end(), s.pixel(0, y), s.pixel(660, y));
    return area;
  };
  const auto settled = [&] {
    std::vector<float> last;
    int same = 0;
    return wait_for([&] {
      std::this_thread::sleep_for(std::chrono::seconds(1));
      std::vector<float> now = canvas_area();
      same = !now.empty() && now == last ? same + 1 : 0;
      last = std::move(now);
      return same >= 2;
    });
  };
  int before = 0;
  ASSERT_TRUE(wait_for([&] { return (before = canvas_width()) > 300; })) << "no canvas";
  EXPECT_TRUE(settled());
  before = canvas_width();
  window.wheel(320, 350, -1);  // a notch down
  int after = 0;
  ASSERT_TRUE(wait_for([&] { return (after = canvas_width()) > 0 && after < before - 20; }))
      << "the wheel did not zoom out";
  EXPECT_TRUE(settled());
  after = canvas_width();
  EXPECT_NEAR(static_cast<double>(before) / after, 1.25, 0.03) << before << " -> " << after;
  fs::remove_all(dir);
}

// Fast colour: a click on a paint's chip in the tool bar loads the brush with it (a recorded
// load of that paint alone), Shift-click adds a part to the Palette's mix without loading,
// and the loaded mix comes back from the recent chips with one click.
TEST(WindowTools, APaintChipLoadsTheBrushAndARecentChipLoadsItAgain) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_paint_strip");
  const fs::path recording = dir / "strip.strokes";
  Window window(dir, recording, {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  // The strip's row in a 1000 x 700 window: chips 18 px wide, 20 apart, from x = 60, in the
  // library's order: the ninth (i = 8) is Orange, the tenth Red. The recent row below it.
  static constexpr int kRowY = 88, kRecentY = 110, kOrange = 8, kRed = 9, kPaints = 15;
  const auto chip_x = [](int i) { return 69 + 20 * i; };
  const auto loads = [&] { return lines_starting(recording, "load "); };
  // The chips appear once the swatches are made: Red's is red.
  ASSERT_TRUE(wait_for([&] {
    const impasto::render::Image s = window.screenshot();
    if (s.width != 1000) return false;
    const float* p = s.pixel(chip_x(kRed), kRowY - 4);  // the masstone's upper half
    return p[0] > p[2] + 0.1f && p[0] > 0.25f;
  })) << "no paint chips in the tool bar";
  const std::size_t before = loads().size();
  window.tap(chip_x(kRed), kRowY);
  ASSERT_TRUE(wait_for([&] { return loads().size() == before + 1; })) << "the click loaded nothing";
  EXPECT_NE(loads().back().find("\"Red\" 1"), std::string::npos) << loads().back();

  window.ctrl_click(chip_x(kOrange), kRowY);  // a part of Orange in the mix: no load
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  EXPECT_EQ(loads().size(), before + 1);

  // The recent Red: its chip follows the paints on their row when there is room, else it
  // starts the row below. A recent chip shows the mix over its tint: its top half is read.
  std::optional<std::array<int, 2>> recent;
  ASSERT_TRUE(wait_for([&] {
    const impasto::render::Image s = window.screenshot();
    if (s.width != 1000) return false;
    for (const auto& [y, from] :
         {std::pair{kRowY - 4, chip_x(kPaints)}, std::pair{kRecentY - 4, 60}}) {
      for (int x = from; x < 660; ++x) {
        const float* p = s.pixel(x, y);
        if (p[0] > p[2] + 0.1f && p[0] > 0.25f && p[1] < 0.3f) {
          recent = {x + 6, y};
          return true;
        }
      }
    }
    return false;
  })) << "no recent chip";
  window.tap((*recent)[0], (*recent)[1]);
  ASSERT_TRUE(wait_for([&] { return loads().size() == before + 2; }))
      << "the recent chip loaded nothing";
  EXPECT_NE(loads().back().find("\"Red\" 1"), std::string::npos) << loads().back();
  EXPECT_EQ(loads().back().find("Orange"), std::string::npos) << loads().back();
  fs::remove_all(dir);
}

}  // namespace
