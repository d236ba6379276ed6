// The window's file dialog, unsaved-changes prompt and notifications, under Xvfb, driven by
// real input events (xdotool): Save as saves where the dialog says and asks before replacing
// a file, the quit prompt's Save / Discard / Cancel do what they say, and a file that cannot
// be opened shows as an error notification. What the window shows is read from its title
// and from screenshots of it (import).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "impasto/render/image.hpp"

namespace {

namespace fs = std::filesystem;
using impasto::render::Image;

// The window's layout at 1200 x 800 (ImGui's default font): the File menu's items, and the
// file dialog (780 x 500, centred) with its fields and buttons.
constexpr int kWindowW = 1200, kWindowH = 800;
constexpr int kFileMenuX = 20, kFileMenuY = 10;
constexpr int kMenuOpenY = 50, kMenuSaveAsY = 106, kMenuQuitY = 143;
constexpr int kDialogX = (kWindowW - 780) / 2, kDialogY = (kWindowH - 500) / 2;
constexpr int kFolderFieldX = kDialogX + 320, kFolderFieldY = kDialogY + 36;
constexpr int kNameFieldX = kDialogX + 300, kNameFieldY = kDialogY + 451;
constexpr int kAcceptX = kDialogX + 726, kAcceptY = kDialogY + 474;

std::string output_of(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  return output;
}

bool wait_for(const std::function<bool()>& ready, double seconds = 60.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
  }
  return false;
}

void xdotool(const std::string& args) {
  ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << args;
}

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

// Over the part of the region the image has (a capture can come back empty or small).
double mean_luma(const Image& image, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
      const float* p = image.pixel(x, y);
      sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

// One painting window, run as a child with its own home, config and state folders.
class PaintingWindow {
 public:
  PaintingWindow(const fs::path& home, std::vector<std::string> args) : home_(home) {
    pid_ = fork();
    if (pid_ == 0) {
      setenv("HOME", home.c_str(), 1);
      setenv("XDG_CONFIG_HOME", (home / ".config").c_str(), 1);
      setenv("XDG_STATE_HOME", (home / ".state").c_str(), 1);
      std::vector<std::string> argv{IMPASTO_EXECUTABLE, "paint",
                                    "--window-width",   std::to_string(kWindowW),
                                    "--window-height",  std::to_string(kWindowH)};
      argv.insert(argv.end(), args.begin(), args.end());
      std::vector<char*> c_args;
      for (auto& a : argv) c_args.push_back(a.data());
      c_args.push_back(nullptr);
      execv(IMPASTO_EXECUTABLE, c_args.data());
      _exit(127);
    }
    wait_for(
        [&] {
          id_ = output_of("xdotool search --pid " + std::to_string(pid_) +
                          " --name ' Impasto$' 2>/dev/null | head -1");
          return !id_.empty();
        },
        60.0);
    // The panels laid out: the status bar has its text.
    if (!id_.empty()) wait_for([&] { return mean_luma(screenshot(), 0, 780, 400, 800) > 0.02; });
  }
  ~PaintingWindow() {
    if (running()) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool up() const { return !id_.empty(); }
  std::string title() const { return output_of("xdotool getwindowname " + id_ + " 2>/dev/null"); }
  bool running() {
    if (exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      exit_status_ = status;
      return false;
    }
    return true;
  }
  int exit_status() const { return exit_status_; }
  Image screenshot() const {
    const fs::path file = home_ / "screen.png";
    // (Bounded: import waits for a window that has gone, holding the display.)
    std::system(
        ("timeout 20 import -window " + id_ + " png:'" + file.string() + "' 2>/dev/null").c_str());
    try {
      return impasto::render::read_png(file);
    } catch (const std::exception&) {
      return Image{};
    }
  }
  void click(int x, int y) const {
    xdotool("mousemove --window " + id_ + " " + std::to_string(x) + " " + std::to_string(y) +
            " sleep 0.1 click 1 sleep 0.1");
  }
  void type(const std::string& text) const { xdotool("type --delay 15 '" + text + "'"); }
  // A stroke across the canvas (left of the panels).
  void paint(int y) const {
    std::string drag = "mousemove --window " + id_ + " 150 " + std::to_string(y) + " mousedown 1";
    for (int x = 160; x <= 500; x += 10) {
      drag += " mousemove --window " + id_ + " " + std::to_string(x) + " " + std::to_string(y);
    }
    xdotool(drag + " mouseup 1");
  }
  // File > item, once the menu is seen open (its dark popup over the white canvas).
  void file_menu(int item_y) const {
    click(kFileMenuX, kFileMenuY);
    ASSERT_TRUE(wait_for([&] {
      const Image s = screenshot();
      return whole(s) && mean_luma(s, 100, 125, 180, 150) < 0.3;
    })) << "the File menu did not open";
    click(40, item_y);
  }
  // The file dialog, seen open: its dark listing over the middle of the canvas.
  bool dialog_open() const {
    const Image s = screenshot();
    return whole(s) && mean_luma(s, 560, 380, 640, 420) < 0.2;
  }
  std::vector<Button> buttons_near_centre() const {
    const Image s = screenshot();
    if (!whole(s)) return {};
    return find_buttons(s, 250, 250, 860, 560);
  }

 private:
  fs::path home_;
  pid_t pid_ = -1;
  std::string id_;
  bool exited_ = false;
  int exit_status_ = -1;
};

fs::path fresh_home(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool have_tools() {
  return std::system("command -v xdotool >/dev/null 2>&1 && command -v import >/dev/null 2>&1") ==
         0;
}

// Save as through the dialog: into a folder typed in its folder field, under a typed name;
// the title follows; saving over it asks first, and Cancel there keeps the file.
TEST(WindowFiles, SaveAsSavesWhereTheDialogSaysAndAsksBeforeReplacing) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_tools()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = fresh_home("impasto_window_save_as");
  const fs::path folder = home / "paintings";
  fs::create_directories(folder);
  PaintingWindow window(home, {});
  ASSERT_TRUE(window.up()) << "the window did not open";
  EXPECT_EQ(window.title(), "Untitled \u2014 Impasto");
  window.paint(300);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 Untitled"); }))
      << window.title();

  window.file_menu(kMenuSaveAsY);
  ASSERT_TRUE(wait_for([&] { return window.dialog_open(); })) << "no Save as dialog";
  window.click(kFolderFieldX, kFolderFieldY);
  window.type(folder.string());
  window.click(kNameFieldX, kNameFieldY);  // leaving the folder field goes there
  window.type("study");
  window.click(kAcceptX, kAcceptY);
  const fs::path saved = folder / "study.impasto";
  ASSERT_TRUE(wait_for([&] { return fs::exists(saved); })) << "nothing saved at " << saved;
  EXPECT_TRUE(wait_for([&] { return window.title() == "study.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_FALSE(fs::exists(home / "study.impasto"));
  // The folder is remembered for the next dialog, in this session and the next.
  EXPECT_NE(contents(home / ".config" / "impasto" / "folders.txt").find(folder.string()),
            std::string::npos);

  // Again over the same file: the dialog opens in that folder with its name; Save asks.
  window.paint(400);
  ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 study"); }));
  const std::string first = contents(saved);
  window.file_menu(kMenuSaveAsY);
  ASSERT_TRUE(wait_for([&] { return window.dialog_open(); }));
  window.click(kAcceptX, kAcceptY);
  std::vector<Button> replace;  // Replace, Cancel
  ASSERT_TRUE(wait_for([&] { return (replace = window.buttons_near_centre()).size() == 2; }))
      << "no question before replacing the file";
  window.click(replace[1].x, replace[1].y);  // Cancel: the file stays as it was
  ASSERT_TRUE(wait_for([&] { return window.buttons_near_centre().empty(); }));
  EXPECT_TRUE(window.dialog_open());
  EXPECT_EQ(contents(saved), first);
  window.click(kAcceptX, kAcceptY);
  ASSERT_TRUE(wait_for([&] { return (replace = window.buttons_near_centre()).size() == 2; }));
  window.click(replace[0].x, replace[0].y);  // Replace
  EXPECT_TRUE(wait_for([&] { return window.title() == "study.impasto \u2014 Impasto"; }))
      << window.title();
  EXPECT_NE(contents(saved), first) << "the second stroke was not saved";
  fs::remove_all(home);
}

// File > Quit over unsaved paint: Cancel keeps the window and the paint, Save as (an
// untitled painting) saves through the dialog and quits; Discard quits without saving.
TEST(WindowFiles, TheQuitPromptsButtonsDoWhatTheySay) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_tools()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = fresh_home("impasto_window_quit");
  {
    PaintingWindow window(home, {});
    ASSERT_TRUE(window.up());
    window.paint(300);
    ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 "); }));
    window.file_menu(kMenuQuitY);
    std::vector<Button> prompt;  // Save as..., Discard, Cancel
    ASSERT_TRUE(wait_for([&] { return (prompt = window.buttons_near_centre()).size() == 3; }))
        << "no Save / Discard / Cancel prompt";
    window.click(prompt[2].x, prompt[2].y);  // Cancel
    ASSERT_TRUE(wait_for([&] { return window.buttons_near_centre().empty(); }));
    EXPECT_TRUE(window.running());
    EXPECT_TRUE(window.title().starts_with("\u2022 Untitled")) << window.title();

    window.file_menu(kMenuQuitY);
    ASSERT_TRUE(wait_for([&] { return (prompt = window.buttons_near_centre()).size() == 3; }));
    window.click(prompt[0].x, prompt[0].y);  // Save as...: the dialog, in home
    ASSERT_TRUE(wait_for([&] { return window.dialog_open(); }));
    window.type("kept");  // the name field has the keyboard, its proposal selected
    window.click(kAcceptX, kAcceptY);
    EXPECT_TRUE(wait_for([&] { return !window.running(); })) << "did not quit after saving";
    EXPECT_EQ(window.exit_status(), 0);
    EXPECT_TRUE(fs::exists(home / "kept.impasto"));
  }
  {
    PaintingWindow window(home, {(home / "kept.impasto").string()});
    ASSERT_TRUE(window.up());
    EXPECT_EQ(window.title(), "kept.impasto \u2014 Impasto");
    const std::string saved = contents(home / "kept.impasto");
    window.paint(450);
    ASSERT_TRUE(wait_for([&] { return window.title().starts_with("\u2022 kept"); }));
    window.file_menu(kMenuQuitY);
    std::vector<Button> prompt;  // Save, Discard, Cancel
    ASSERT_TRUE(wait_for([&] { return (prompt = window.buttons_near_centre()).size() == 3; }));
    window.click(prompt[1].x, prompt[1].y);  // Discard
    EXPECT_TRUE(wait_for([&] { return !window.running(); })) << "did not quit on Discard";
    EXPECT_EQ(window.exit_status(), 0);
    EXPECT_EQ(contents(home / "kept.impasto"), saved) << "Discard wrote the painting";
  }
  fs::remove_all(home);
}

// A file that is not a painting, opened through the dialog: the error is a notification
// (red, lower left, over the canvas), and stays until dismissed.
TEST(WindowFiles, AnErrorShowsAsANotification) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  if (!have_tools()) GTEST_SKIP() << "xdotool or ImageMagick's import is not installed";
  const fs::path home = fresh_home("impasto_window_error");
  std::ofstream(home / "broken.impasto") << "not a painting";
  PaintingWindow window(home, {});
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
  window.file_menu(kMenuOpenY);
  ASSERT_TRUE(wait_for([&] { return window.dialog_open(); }));
  window.type("broken.impasto");
  window.click(kAcceptX, kAcceptY);
  EXPECT_TRUE(wait_for([&] { return red_pixels() > 3000; })) << "no error notification";
  EXPECT_EQ(window.title(), "Untitled \u2014 Impasto");  // nothing was opened
  fs::remove_all(home);
}

}  // namespace
