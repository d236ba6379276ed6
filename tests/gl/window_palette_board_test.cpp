// The palette board under a real pointer (xdotool, under Xvfb): two pigments chosen in the
// Palette panel are laid out as blobs, scrubbed together with the board's brush in a few
// passes, and "Pick up onto brush" loads the canvas brush with both; a stroke on the canvas
// then paints with that mix. (Its headless tests passed while the window loaded nothing.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "window_driver.hpp"

namespace {

using namespace impasto::window_test;

// The window's layout at 1000 x 700 (ImGui's default font): the Palette panel's rows of
// pigment parts (the database's order) and the board under them.
constexpr int kPartsX = 778, kFirstPartY = 207, kPartRowY = 23;
constexpr int kBlueGreenRow = 2, kColdYellowRow = 4;
constexpr int kBoardY = 500, kFirstBlobX = 740, kSecondBlobX = 820;
constexpr int kLayOutX = 688, kMixX = 810, kToolY = 632;
constexpr int kPickUpX = 745, kPickUpY = 655;

// The pigment names and parts of a recorded `load` line.
std::vector<std::string> loaded_pigments(const std::string& line) {
  std::vector<std::string> names;
  for (std::size_t open = line.find('"'); open != std::string::npos;) {
    const std::size_t close = line.find('"', open + 1);
    if (close == std::string::npos) break;
    names.push_back(line.substr(open + 1, close - open - 1));
    open = line.find('"', close + 1);
  }
  return names;
}

// Pigment parts are set as a user types them: ctrl+click makes the slider a text field.
void set_parts(Window& window, int row, const std::string& parts) {
  window.ctrl_click(kPartsX, kFirstPartY + row * kPartRowY);
  window.key("ctrl+a");
  window.type(parts);
  window.key("Return");
}

TEST(WindowPaletteBoard, ScrubbingTwoBlobsLoadsTheBrushWithBoth) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path dir = test_dir("impasto_window_palette_board");
  const fs::path recording = dir / "session.strokes";
  Window window(dir, recording, {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  // The panels laid out: the board's clean white ground where the blobs go.
  // The colour on screen at x on the board's middle row (black before the window shows).
  const auto board_at = [&](int x) {
    std::array<float, 3> rgb{};
    const impasto::render::Image shot = window.screenshot(dir / "window.png");
    if (shot.width >= 1000 && shot.height >= 700)
      std::copy_n(shot.pixel(x, kBoardY), 3, rgb.begin());
    return rgb;
  };
  ASSERT_TRUE(wait_for([&] {
    const auto p = board_at(kSecondBlobX);
    return std::min({p[0], p[1], p[2]}) > 0.8f;
  })) << "no palette board on screen";

  // A click the window missed (the first after it opens can be) is seen on the screen and
  // made again.
  const auto click_until = [&](int x, int y, const std::function<bool()>& shown) {
    for (int attempt = 0; attempt < 5; ++attempt) {
      window.click(x, y);
      if (wait_for(shown, 5s)) return true;
    }
    return false;
  };
  // A radio button is chosen when its centre is filled with ImGui's blue.
  const auto chosen = [&](int x) {
    std::array<float, 3> rgb{};
    const impasto::render::Image shot = window.screenshot(dir / "window.png");
    if (shot.width >= 1000 && shot.height >= 700)
      std::copy_n(shot.pixel(x, kToolY), 3, rgb.begin());
    return rgb[2] > 0.8f && rgb[0] < 0.5f;
  };

  // A blob of Cold Yellow, then one of Blue Green Shade beside it.
  ASSERT_TRUE(click_until(kLayOutX, kToolY, [&] { return chosen(kLayOutX); }));
  set_parts(window, kColdYellowRow, "1");
  ASSERT_TRUE(click_until(kFirstBlobX, kBoardY,
                          [&] {
                            const auto yellow = board_at(kFirstBlobX);
                            return yellow[0] > yellow[2] + 0.1f;
                          }))
      << "no yellow blob (" << dir / "window.png"
      << ")";
  set_parts(window, kColdYellowRow, "0");
  set_parts(window, kBlueGreenRow, "1");
  ASSERT_TRUE(click_until(kSecondBlobX, kBoardY,
                          [&] {
                            const auto blue = board_at(kSecondBlobX);
                            return blue[2] > blue[0] + 0.1f;
                          }))
      << "no blue blob (" << dir / "window.png"
      << ")";

  // Three passes of the board's brush through both blobs, then the pick-up. A pass the
  // window has not seen yet (a loaded machine) gives a board brush that holds one pigment
  // or none: scrub again until the pick-up carries both.
  ASSERT_TRUE(click_until(kMixX, kToolY, [&] { return chosen(kMixX); }));
  std::vector<std::string> loads, pigments;
  for (int attempt = 0; attempt < 4 && pigments.size() < 2; ++attempt) {
    for (int pass = 0; pass < 3; ++pass) window.scrub(kFirstBlobX - 30, kSecondBlobX + 40, kBoardY);
    window.click(kPickUpX, kPickUpY);
    wait_for(
        [&] {
          loads = lines_starting(recording, "load ");
          return !loads.empty();
        },
        10s);
    pigments = loads.empty() ? std::vector<std::string>{} : loaded_pigments(loads.back());
  }
  ASSERT_FALSE(loads.empty()) << "Pick up onto brush loaded nothing:\n" << read_text(recording);
  std::sort(pigments.begin(), pigments.end());
  EXPECT_EQ(pigments, (std::vector<std::string>{"Blue Green Shade", "Cold Yellow"}))
      << loads.back();
  EXPECT_FALSE(lines_starting(recording, "wipe").empty()) << "the brush is wiped first";

  // The loaded brush paints on the canvas.
  const std::size_t pens_before = lines_starting(recording, "pen ").size();
  window.scrub(100, 500, 300);
  EXPECT_TRUE(wait_for([&] { return lines_starting(recording, "pen ").size() > pens_before; }));
  fs::remove_all(dir);
}

}  // namespace
