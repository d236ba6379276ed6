#pragma once
// The window's shell: GLFW and Dear ImGui from start to end, the signals that close the
// window, the title and cursor, the raw input as it arrives (each mouse event with the window
// system's time, each key press, each wheel click), and presenting frames. It knows nothing
// of paint: the frame loop (paint_window.cpp) asks it for input and hands it what to show.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <impasto/render_gl/shaded_view_cache.hpp>

#include "window/pointer_events.hpp"
#include "window/ui_damage.hpp"

struct GLFWwindow;
struct GLFWcursor;

namespace impasto::app::window {

class PointerServerTimes;
class WindowPresenter;

struct KeyPress {
  int key, mods;  // GLFW's key and modifier bits
  bool repeat;    // a held key's repeat
};

class WindowShell {
 public:
  // Opens a window of width x height with an OpenGL 3.3 core context and ImGui over it;
  // throws std::runtime_error when there is no display or no such context.
  WindowShell(int width, int height, const std::string& title);
  ~WindowShell();
  WindowShell(const WindowShell&) = delete;
  WindowShell& operator=(const WindowShell&) = delete;

  GLFWwindow* glfw() const { return window_; }
  double now_s() const;  // GLFW's clock, the one every input time is on

  // SIGTERM, SIGINT and SIGHUP (a logout, Ctrl+C) close the window at the next frame, keeping
  // unsaved work recoverable instead of asking.
  static void close_on_signals();
  static bool signalled();

  // Delivers the window system's events (times read first); then whether the window's close
  // button was pressed since (the request is taken: the caller decides).
  void poll();
  bool take_close_request();

  std::vector<PointerEvent> take_pointer_events() { return pointer_events_.take(); }
  std::vector<KeyPress> take_key_presses() { return std::exchange(key_presses_, {}); }
  std::vector<double> take_wheel_times() { return std::exchange(wheel_times_, {}); }
  // How many mouse events had the window system's own time, and how many their delivery's.
  std::size_t server_timed() const;
  std::size_t delivery_timed() const;

  void window_size(int& w, int& h) const;
  void framebuffer_size(int& w, int& h) const;
  void cursor(double& x, double& y) const;
  // Where the window lies on the desktop, and the primary screen's rectangle (x, y, w, h;
  // the window's own without a monitor): a tablet maps its pen onto the screen.
  std::array<double, 2> window_origin_px() const;
  std::array<double, 4> screen_px() const;
  bool key_down(int key) const;
  void set_title(const std::string& title);
  // The crosshair (while the eyedropper would pick; ImGui leaves the cursor alone meanwhile).
  void set_crosshair(bool on);

  void begin_ui_frame();  // ImGui's NewFrame for both backends
  // Presents the frame drawn by `draw_canvas(rect)` (the canvas's pixels of a GL rectangle)
  // with ImGui's panels over it: the whole window, or where the back buffer keeps the last
  // frame only what changed (the canvas's re-shaded rectangles and the panels' changed parts).
  // `ui_textures_changed`: ImGui images whose pixels changed though their quads did not.
  // `screenshot`: also save the whole frame to this file.
  void present(std::span<const render_gl::PixelRect> canvas_changed,
               std::span<const std::uintptr_t> ui_textures_changed, double fb_scale,
               const std::filesystem::path* screenshot,
               const std::function<void(const render_gl::PixelRect&)>& draw_canvas);
  // A frame of the panels over a plain background; the next frame is presented whole.
  void present_over_background(const std::array<float, 3>& background_rgb);

 private:
  struct Glfw {
    Glfw();
    ~Glfw();
  };

  Glfw glfw_;
  GLFWwindow* window_ = nullptr;
  GLFWcursor* crosshair_ = nullptr;
  bool crosshair_on_ = false;
  std::unique_ptr<PointerServerTimes> server_times_;
  PointerEventQueue pointer_events_;
  std::vector<KeyPress> key_presses_;
  std::vector<double> wheel_times_;
  bool close_requested_ = false;
  std::unique_ptr<WindowPresenter> presenter_;
  UiDamage ui_damage_;
  bool present_whole_ = true;  // the window's pixels may be lost: the next frame shows them all
  int presented_w_ = 0, presented_h_ = 0;
  std::string shown_title_;
};

// Whether ImGui's last frame drew something that takes a mouse press at (x, y): a panel, the
// menu bar, the status bar, or any open popup (a menu, the unsaved-changes prompt).
bool ui_at(double x, double y);
// ImGui has the keyboard: a text field, a dialog or a menu.
bool ui_has_keyboard();

}  // namespace impasto::app::window
