#pragma once
// Driving the painting window under Xvfb with real X input (xdotool) and reading what it shows
// (ImageMagick's import): what the window tests share. A window runs as a child process with
// config and recovery folders of its own, recording its session to a stroke file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

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

// One painting window of its own (config and recovery folders in `dir`), recording to
// `recording`; closed with SIGTERM at the end.
class Window {
 public:
  // `state`: the recovery folder's parent, in `dir` (a window killed with unsaved work is
  // offered for recovery by the next window sharing it).
  Window(const fs::path& dir, const fs::path& recording, const std::vector<std::string>& args,
         const std::string& state = "state") {
    pid_ = fork();
    if (pid_ == 0) {
      setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);
      setenv("XDG_STATE_HOME", (dir / state).c_str(), 1);
      std::vector<std::string> all{
          IMPASTO_EXECUTABLE, "paint", "--record",        recording.string(),
          "--window-width",   "1000",  "--window-height", "700"};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(IMPASTO_EXECUTABLE, argv.data());
      _exit(127);
    }
    // Up once its window is mapped and its session has begun recording.
    const std::string search = "xdotool search --onlyvisible --pid " + std::to_string(pid_);
    up_ = wait_for(
        [&] {
          id_ = run_output(search + " | head -1");
          while (!id_.empty() && (id_.back() == '\n' || id_.back() == ' ')) id_.pop_back();
          return !id_.empty() && fs::exists(recording) && fs::file_size(recording) > 0;
        },
        120s);
  }
  ~Window() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool up() const { return up_; }

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
  void type(const std::string& text) { xdotool("type --delay 30 '" + text + "'"); }
  impasto::render::Image screenshot(const fs::path& png) {
    run_output("import -window " + id_ + " '" + png.string() + "'");
    return impasto::render::read_png(png);
  }

 private:
  static std::string pos(int x, int y) { return std::to_string(x) + " " + std::to_string(y); }
  static void xdotool(const std::string& args) {
    EXPECT_EQ(std::system(("xdotool " + args).c_str()), 0) << args;
  }
  pid_t pid_ = -1;
  std::string id_;
  bool up_ = false;
};

// A fresh folder for one test's files.
inline fs::path test_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace impasto::window_test
