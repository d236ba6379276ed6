#pragma once
// Driving the painting window under Xvfb with real X input (xdotool) and reading what it shows
// (ImageMagick's import): what the window tests share. A window runs as a child process with
// config and recovery folders of its own, recording its session to a stroke file.
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
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "impasto/render/image.hpp"

namespace impasto::window_test {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

inline std::string run_output(const std::string& command, int* status = nullptr) {
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int code = pclose(pipe);
  if (status) *status = code;
  return output;
}

inline bool have_xdotool() {
  return std::system("command -v xdotool >/dev/null 2>&1 && command -v import >/dev/null 2>&1") ==
         0;
}

// Waits for `done`, up to `limit` (a loaded 2-core machine is slow, never assume a speed).
inline bool wait_for(const std::function<bool()>& done, std::chrono::milliseconds limit = 60s) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(100ms);
  }
  return done();
}

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> lines_starting(const fs::path& file, const std::string& prefix) {
  std::vector<std::string> found;
  std::istringstream in(read_text(file));
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) found.push_back(line);
  return found;
}

// Over the part of the region the image has (a capture can come back empty or small).
inline double mean_luma(const impasto::render::Image& image, int x0, int y0, int x1, int y1) {
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

// How a window is started.
// The luma of the view's background (render_gl::GpuViewOptions::background_rgb).
inline constexpr double kBackgroundLuma = 0.2126 * 0.16 + 0.7152 * 0.16 + 0.0722 * 0.18;

struct WindowSetup {
  std::vector<std::string> args;      // after `impasto paint`
  std::optional<fs::path> recording;  // --record: the window is up once it has begun
  int width = 1000, height = 700;
  // Its config and state folders, in the test's folder (a window killed with unsaved work is
  // offered for recovery by the next window sharing the state folder).
  std::string config = "config", state = "state";
  bool home = false;  // HOME is the test's folder too (where the file dialog starts)
};

// One painting window of its own (config and recovery folders in `dir`), closed with SIGTERM
// at the end unless it has exited.
class Window {
 public:
  // Recording to `recording`; `state`: the recovery folder's parent, in `dir`.
  Window(const fs::path& dir, const fs::path& recording, const std::vector<std::string>& args,
         const std::string& state = "state")
      : Window(dir, WindowSetup{args, recording, 1000, 700, "config", state, false}) {}

  Window(const fs::path& dir, const WindowSetup& setup) : dir_(dir) {
    pid_ = fork();
    if (pid_ == 0) {
      if (setup.home) {  // started from home, as a desktop launcher starts it
        setenv("HOME", dir.c_str(), 1);
        if (chdir(dir.c_str()) != 0) _exit(126);
      }
      setenv("XDG_CONFIG_HOME", (dir / setup.config).c_str(), 1);
      setenv("XDG_STATE_HOME", (dir / setup.state).c_str(), 1);
      std::vector<std::string> all{IMPASTO_EXECUTABLE, "paint",
                                   "--window-width",   std::to_string(setup.width),
                                   "--window-height",  std::to_string(setup.height)};
      if (setup.recording) all.insert(all.end(), {"--record", setup.recording->string()});
      all.insert(all.end(), setup.args.begin(), setup.args.end());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(IMPASTO_EXECUTABLE, argv.data());
      _exit(127);
    }
    // Up once its window is mapped, with a recording its session has begun recording, without
    // one its panels are laid out (the status bar has its text), and the painting shows.
    const std::string search = "xdotool search --onlyvisible --pid " + std::to_string(pid_);
    up_ = wait_for(
        [&] {
          id_ = run_output(search + " 2>/dev/null | head -1");
          while (!id_.empty() && (id_.back() == '\n' || id_.back() == ' ')) id_.pop_back();
          if (id_.empty()) return false;
          if (setup.recording &&
              !(fs::exists(*setup.recording) && fs::file_size(*setup.recording) > 0))
            return false;
          const impasto::render::Image shown = screenshot();
          if (!setup.recording &&
              !(mean_luma(shown, 0, setup.height - 20, 400, setup.height) > 0.02))
            return false;
          // ...and the painting is shown: the first frames show the view's background and a
          // note where the canvas will be (app/window/opening_note.hpp), whose dark menus
          // and dialogs a test cannot tell apart from it.
          const int x = (setup.width - 360) / 2, y = setup.height / 2 + 60;
          return std::abs(mean_luma(shown, x - 8, y - 8, x + 8, y + 8) - kBackgroundLuma) > 0.02;
        },
        120s);
  }
  ~Window() {
    if (running()) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
  bool up() const { return up_; }
  // False once the program has exited (it is reaped then: exit_status() says how).
  bool running() {
    if (pid_ <= 0 || exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      exit_status_ = status;
    }
    return !exited_;
  }
  int exit_status() const { return exit_status_; }
  std::string title() const {
    std::string name = run_output("xdotool getwindowname " + id_ + " 2>/dev/null");
    while (!name.empty() && name.back() == '\n') name.pop_back();
    return name;
  }

  // xdotool commands, positions relative to the window.
  void move(int x, int y) { xdotool("mousemove --window " + id_ + " " + pos(x, y)); }
  // ImGui (1.86) reads the mouse once a frame, and a frame on a loaded machine may take a
  // few hundred ms: the cursor rests, the button is held and let go, each for longer.
  void click(int x, int y) {
    move(x, y);
    std::this_thread::sleep_for(400ms);
    xdotool("mousedown 1");
    std::this_thread::sleep_for(400ms);
    xdotool("mouseup 1");
    std::this_thread::sleep_for(400ms);
  }
  // A press and release at once, for a control whose effect the test then waits for (the
  // GLFW backend keeps a press made between two frames for the next one): quicker than
  // click(), which holds the button for controls that act while held.
  void tap(int x, int y) {
    xdotool("mousemove --window " + id_ + " " + pos(x, y) + " sleep 0.1 click 1 sleep 0.1");
  }
  // The button held from x0 to x1 along row y, a motion event every 10 pixels: a quick stroke.
  void drag(int x0, int x1, int y) {
    std::string moves = "mousemove --window " + id_ + " " + pos(x0, y) + " mousedown 1";
    const int step = x1 > x0 ? 10 : -10;
    for (int x = x0 + step; (x1 - x) * step >= 0; x += step)
      moves += " mousemove --window " + id_ + " " + pos(x, y);
    xdotool(moves + " mouseup 1");
  }
  // `notches` wheel clicks at (x, y): up (zoom in) when positive, down when negative.
  void wheel(int x, int y, int notches) {
    move(x, y);
    std::this_thread::sleep_for(150ms);
    for (int i = 0; i < std::abs(notches); ++i)
      xdotool(std::string("click ") + (notches > 0 ? "4" : "5") + " sleep 0.1");
  }
  // Ctrl + click (it makes an ImGui slider a text field).
  void ctrl_click(int x, int y) {
    move(x, y);
    std::this_thread::sleep_for(150ms);
    xdotool("keydown ctrl sleep 0.1 click 1 sleep 0.1 keyup ctrl");
  }
  // The button held from x0 to x1 along row y and back, a motion event every 5 pixels.
  void scrub(int x0, int x1, int y) {
    std::string moves = "mousemove --window " + id_ + " " + pos(x0, y) + " mousedown 1";
    const int step = x1 > x0 ? 5 : -5;
    for (int x = x0; (x1 - x) * step > 0; x += step)
      moves += " mousemove --window " + id_ + " " + pos(x, y) + " sleep 0.01";
    for (int x = x1; (x - x0) * step > 0; x -= step)
      moves += " mousemove --window " + id_ + " " + pos(x, y + 2) + " sleep 0.01";
    xdotool(moves + " mouseup 1");
    std::this_thread::sleep_for(300ms);
  }
  // Keys (xdotool's names, space-separated), each held for a moment: ImGui 1.86 reads a key's
  // state once a frame, so a press and release within one frame would be lost.
  void key(const std::string& keys) {
    std::istringstream names(keys);
    std::string name, presses;
    while (names >> name) presses += " keydown " + name + " sleep 0.06 keyup " + name;
    if (!presses.empty()) xdotool(presses.substr(1));
  }
  // Text typed into the field with the keyboard, a key every `delay_ms`.
  void type(const std::string& text, int delay_ms = 30) {
    xdotool("type --delay " + std::to_string(delay_ms) + " '" + text + "'");
  }
  // The window as it shows now, saved to `png` too; an empty image if it could not be taken.
  // (Bounded: import waits for a window that has gone, holding the display.)
  impasto::render::Image screenshot(const fs::path& png) const {
    run_output("timeout 20 import -window " + id_ + " png:'" + png.string() + "'");
    try {
      return impasto::render::read_png(png);
    } catch (const std::exception&) {
      return {};
    }
  }
  impasto::render::Image screenshot() const { return screenshot(dir_ / "screen.png"); }

 private:
  static std::string pos(int x, int y) { return std::to_string(x) + " " + std::to_string(y); }
  static void xdotool(const std::string& args) {
    EXPECT_EQ(std::system(("xdotool " + args).c_str()), 0) << args;
  }
  fs::path dir_;
  pid_t pid_ = -1;
  std::string id_;
  bool up_ = false;
  bool exited_ = false;
  int exit_status_ = -1;
};

// A fresh folder for one test's files.
inline fs::path test_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace impasto::window_test
