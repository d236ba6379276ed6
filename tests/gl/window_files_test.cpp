// The window's file dialog, unsaved-changes prompt and notifications, under Xvfb, driven by
// real input events (xdotool): Save as saves where the dialog says and asks before replacing
// a file, the quit prompt's Save / Discard / Cancel do what they say, and a file that cannot
// be opened shows as an error notification, and Save asks before replacing a file another
// window saved meanwhile. What the window shows is read from its title
// and from screenshots of it (import).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "window_driver.hpp"

namespace {

using namespace impasto::window_test;
using impasto::render::Image;

// The window's layout at 1200 x 800 (ImGui's default font): the File menu's items, and the
// file dialog (780 x 500, centred) with its fields and buttons.
constexpr int kWindowW = 1200, kWindowH = 800;
constexpr int kFileMenuX = 20, kFileMenuY = 10;
constexpr int kMenuOpenY = 50, kMenuSaveAsY = 106, kMenuQuitY = 162;
constexpr int kDialogX = (kWindowW - 780) / 2, kDialogY = (kWindowH - 500) / 2;
constexpr int kFolderFieldX = kDialogX + 320, kFolderFieldY = kDialogY + 36;
constexpr int kNameFieldX = kDialogX + 300, kNameFieldY = kDialogY + 451;
constexpr int kAcceptX = kDialogX + 726, kAcceptY = kDialogY + 474;

// A capture of the whole window.
bool whole(const Image& image) {
  return image.width == kWindowW && image.height == kWindowH;
}

// A button: one of ImGui's blue rectangles 80-110 px wide, found on a screenshot.
struct Button {
  int x, y;
};

bool button_blue(const float* p) {
  return p[2] > p[0] + 0.12f && p[2] > p[1] + 0.06f && p[0] < 0.4f && p[2] > 0.25f;
}

// The buttons inside a region, left to right (their centres).
std::vector<Button> find_buttons(const Image& image, int x0, int y0, int x1, int y1) {
  struct Run {
    int x0, x1, y0, y1;
  };
  std::vector<Run> runs;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    int x = std::max(0, x0);
    const int end = std::min(image.width, x1);
    while (x < end) {
      if (!button_blue(image.pixel(x, y))) {
        ++x;
        continue;
      }
      const int start = x;
      while (x < end && button_blue(image.pixel(x, y))) ++x;
      if (x - start < 80 || x - start > 110) continue;
      auto same = std::find_if(runs.begin(), runs.end(), [&](const Run& r) {
        // (Rows through the button's label are broken by the text: its rows above and
        // below the label belong to one button.)
        return std::abs(r.x0 - start) <= 2 && std::abs(r.x1 - x) <= 2 && y - r.y1 <= 16;
      });
      if (same != runs.end()) {
        same->y1 = y;
      } else {
        runs.push_back({start, x, y, y});
      }
    }
  }
  std::vector<Button> buttons;
  for (const Run& r : runs) {
    if (r.y1 - r.y0 >= 10) buttons.push_back({(r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2});
  }
  std::sort(buttons.begin(), buttons.end(), [](Button a, Button b) { return a.x < b.x; });
  return buttons;
}

// The window's menus and dialogs, read from its screenshots.
// File > item, once the menu is seen open (its dark popup over the white canvas).
void file_menu(Window& window, int item_y) {
  window.tap(kFileMenuX, kFileMenuY);
  ASSERT_TRUE(wait_for([&] {
    const Image s = window.screenshot();
    return whole(s) && mean_luma(s, 100, 125, 180, 150) < 0.3;
  })) << "the File menu did not open";
  window.tap(40, item_y);
}

// The file dialog, seen open: its dark listing over the middle of the canvas.
bool dialog_open(const Window& window) {
  const Image s = window.screenshot();
  return whole(s) && mean_luma(s, 560, 380, 640, 420) < 0.2;
}

std::vector<Button> buttons_near_centre(const Window& window) {
  const Image s = window.screenshot();
  if (!whole(s)) return {};
  return find_buttons(s, 250, 250, 860, 560);
}

// A stroke across the canvas (left of the panels).
void paint(Window& window, int y) {
  window.scrub(150, 500, y);
}

// A window of its own whose home is `home` (the file dialog starts there), with hidden
// config and state folders in it.
WindowSetup at_home(std::vector<std::string> args = {}) {
  WindowSetup setup;
  setup.args = std::move(args);
  setup.width = kWindowW;
  setup.height = kWindowH;
  setup.config = ".config";
  setup.state = ".state";
  setup.home = true;
  return setup;
}

// Save as through the dialog: into a folder typed in its folder field, under a typed name;
// the title follows; saving over it asks first, and Cancel there keeps the file.
TEST(WindowFiles, SaveAsSavesWhereTheDialogSaysAndAsksBeforeReplacing) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = test_dir("impasto_window_save_as");
  const fs::path folder = home / "paintings";
  fs::create_directories(folder);
  Window window(home, at_home());
  ASSERT_TRUE(window.up()) << "the window did not open";
  EXPECT_EQ(window.title(), "Untitled \u2014 Impasto");
  paint(window, 300);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 Untitled"); }))
      << window.title();

  file_menu(window, kMenuSaveAsY);
  ASSERT_TRUE(wait_for([&] { return dialog_open(window); })) << "no Save as dialog";
  window.tap(kFolderFieldX, kFolderFieldY);
  window.type(folder.string(), 15);
  window.tap(kNameFieldX, kNameFieldY);  // leaving the folder field goes there
  window.type("study", 15);
  window.tap(kAcceptX, kAcceptY);
  const fs::path saved = folder / "study.impasto";
  ASSERT_TRUE(wait_for([&] { return fs::exists(saved); })) << "nothing saved at " << saved;
  EXPECT_TRUE(wait_for([&] { return window.title() == "study.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_FALSE(fs::exists(home / "study.impasto"));
  // The folder is remembered for the next dialog, in this session and the next.
  EXPECT_NE(read_text(home / ".config" / "impasto" / "folders.txt").find(folder.string()),
            std::string::npos);

  // Again over the same file: the dialog opens in that folder with its name; Save asks.
  paint(window, 400);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 study"); }));
  const std::string first = read_text(saved);
  file_menu(window, kMenuSaveAsY);
  ASSERT_TRUE(wait_for([&] { return dialog_open(window); }));
  window.tap(kAcceptX, kAcceptY);
  std::vector<Button> replace;  // Replace, Cancel
  ASSERT_TRUE(wait_for([&] { return (replace = buttons_near_centre(window)).size() == 2; }))
      << "no question before replacing the file";
  window.tap(replace[1].x, replace[1].y);  // Cancel: the file stays as it was
  ASSERT_TRUE(wait_for([&] { return buttons_near_centre(window).empty(); }));
  EXPECT_TRUE(dialog_open(window));
  EXPECT_EQ(read_text(saved), first);
  window.tap(kAcceptX, kAcceptY);
  ASSERT_TRUE(wait_for([&] { return (replace = buttons_near_centre(window)).size() == 2; }));
  window.tap(replace[0].x, replace[0].y);  // Replace
  EXPECT_TRUE(wait_for([&] { return window.title() == "study.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_NE(read_text(saved), first) << "the second stroke was not saved";
  fs::remove_all(home);
}

// File > Quit over unsaved paint: Cancel keeps the window and the paint, Save as (an
// untitled painting) saves through the dialog and quits; Discard quits without saving.
TEST(WindowFiles, TheQuitPromptsButtonsDoWhatTheySay) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = test_dir("impasto_window_quit");
  {
    Window window(home, at_home());
    ASSERT_TRUE(window.up());
    paint(window, 300);
    ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 "); }));
    file_menu(window, kMenuQuitY);
    std::vector<Button> prompt;  // Save as..., Discard, Cancel
    ASSERT_TRUE(wait_for([&] { return (prompt = buttons_near_centre(window)).size() == 3; }))
        << "no Save / Discard / Cancel prompt";
    window.tap(prompt[2].x, prompt[2].y);  // Cancel
    ASSERT_TRUE(wait_for([&] { return buttons_near_centre(window).empty(); }));
    EXPECT_TRUE(window.running());
    EXPECT_TRUE(window.title().starts_with("\u2022 Untitled")) << window.title();

    file_menu(window, kMenuQuitY);
    ASSERT_TRUE(wait_for([&] { return (prompt = buttons_near_centre(window)).size() == 3; }));
    window.tap(prompt[0].x, prompt[0].y);  // Save as...: the dialog, in home
    ASSERT_TRUE(wait_for([&] { return dialog_open(window); }));
    window.type("kept", 15);  // the name field has the keyboard, its proposal selected
    window.tap(kAcceptX, kAcceptY);
    EXPECT_TRUE(wait_for([&] { return !window.running(); })) << "did not quit after saving";
    EXPECT_EQ(window.exit_status(), 0);
    EXPECT_TRUE(fs::exists(home / "kept.impasto"));
  }
  {
    Window window(home, at_home({(home / "kept.impasto").string()}));
    ASSERT_TRUE(window.up());
    EXPECT_EQ(window.title(), "kept.impasto \u2014 Impasto");
    const std::string saved = read_text(home / "kept.impasto");
    paint(window, 450);
    ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 kept"); }));
    file_menu(window, kMenuQuitY);
    std::vector<Button> prompt;  // Save, Discard, Cancel
    ASSERT_TRUE(wait_for([&] { return (prompt = buttons_near_centre(window)).size() == 3; }));
    window.tap(prompt[1].x, prompt[1].y);  // Discard
    EXPECT_TRUE(wait_for([&] { return !window.running(); })) << "did not quit on Discard";
    EXPECT_EQ(window.exit_status(), 0);
    EXPECT_EQ(read_text(home / "kept.impasto"), saved) << "Discard wrote the painting";
  }
  fs::remove_all(home);
}

// A file that is not a painting, opened through the dialog: the error is a notification
// (red, lower left, over the canvas), and stays until dismissed.
TEST(WindowFiles, AnErrorShowsAsANotification) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = test_dir("impasto_window_error");
  std::ofstream(home / "broken.impasto") << "not a painting";
  Window window(home, at_home());
  ASSERT_TRUE(window.up());
  const auto red_pixels = [&] {
    const Image s = window.screenshot();
    int red = 0;
    if (!whole(s)) return 0;
    for (int y = 500; y < 775; ++y) {
      for (int x = 10; x < 460; ++x) {
        const float* p = s.pixel(x, y);
        red += p[0] > 0.35f && p[0] > 2.5f * p[1] && p[0] > 2.5f * p[2];
      }
    }
    return red;
  };
  EXPECT_LT(red_pixels(), 100);
  file_menu(window, kMenuOpenY);
  ASSERT_TRUE(wait_for([&] { return dialog_open(window); }));
  window.type("broken.impasto", 15);
  window.tap(kAcceptX, kAcceptY);
  EXPECT_TRUE(wait_for([&] { return red_pixels() > 3000; })) << "no error notification";
  EXPECT_EQ(window.title(), "Untitled \u2014 Impasto");  // nothing was opened
  fs::remove_all(home);
}

// One painting saved from two places: Save notices that the file changed on disk since this
// window opened it and asks (Overwrite, Save as..., Reload, Cancel) instead of replacing the
// other's work. Cancel keeps it; Overwrite replaces it; the window's own save is then known,
// and the next Save goes straight through.
TEST(WindowFiles, SaveAsksWhenTheFileChangedOnDisk) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_xdotool()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = test_dir("impasto_window_changed_on_disk");
  const fs::path shared = home / "shared.impasto";
  impasto::paintcore::Painting({96, 64, 150.0, 0}).save(shared);
  Window window(home, at_home({shared.string()}));
  ASSERT_TRUE(window.up());
  EXPECT_EQ(window.title(), "shared.impasto \u2014 Impasto");

  // Another window saves its own painting over the file.
  impasto::paintcore::Painting({128, 96, 150.0, 0}).save(shared);
  const std::string theirs = read_text(shared);
  paint(window, 300);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 shared"); }));
  window.key("ctrl+s");
  std::vector<Button> prompt;  // Overwrite, Save as..., Reload, Cancel
  ASSERT_TRUE(wait_for([&] { return (prompt = buttons_near_centre(window)).size() == 4; }))
      << "Save replaced a file changed on disk without asking";
  EXPECT_EQ(read_text(shared), theirs);
  window.tap(prompt[3].x, prompt[3].y);  // Cancel: their painting stays
  ASSERT_TRUE(wait_for([&] { return buttons_near_centre(window).empty(); }));
  EXPECT_EQ(read_text(shared), theirs);
  EXPECT_TRUE(window.title().starts_with("\u2022 shared")) << window.title();

  window.key("ctrl+s");
  ASSERT_TRUE(wait_for([&] { return (prompt = buttons_near_centre(window)).size() == 4; }));
  window.tap(prompt[0].x, prompt[0].y);  // Overwrite
  ASSERT_TRUE(wait_for([&] { return window.title() == "shared.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_NE(read_text(shared), theirs);
  EXPECT_EQ(impasto::paintcore::Painting::load(shared).canvas().width_cells(), 96);

  // Its own save is known: the next Save asks nothing.
  paint(window, 420);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 shared"); }));
  window.key("ctrl+s");
  EXPECT_TRUE(wait_for([&] { return window.title() == "shared.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_TRUE(buttons_near_centre(window).empty());
  fs::remove_all(home);
}

}  // namespace
