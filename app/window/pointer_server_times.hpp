#pragma once
// The window system's own time of each mouse event. GLFW's callbacks do not pass it on, so
// without it an event's time is when glfwPollEvents delivered it: every event that waited
// in the queue while a frame was drawn would get nearly the same time. On X11 each event
// carries the server's time (ms, CLOCK_MONOTONIC on a local server): the frame scans the
// queue before glfwPollEvents, and each callback takes the time of the first scanned event
// that matches it (GLFW drops some events, e.g. moves to where the cursor already is).
#include <cstdint>
#include <optional>
#include <vector>

struct GLFWwindow;

namespace impasto::app::window {

// A server time (ms since some point of the server's clock, wrapping at 2^32) on the GLFW
// clock, given both clocks read now: mono_now_s on CLOCK_MONOTONIC (the server's clock when
// it runs on this machine), glfw_now_s from glfwGetTime. None when the event would be in
// the future or older than max_age_s: a server on another clock (a remote display).
std::optional<double> server_time_on_glfw_clock(std::uint32_t server_ms, double mono_now_s,
                                                double glfw_now_s, double max_age_s = 2.0);

// The scanned events, matched to GLFW's callbacks in order. Window coordinates are whole
// pixels on X11, as GLFW passes them on.
class ServerTimeMatcher {
 public:
  void clear() { stamps_.clear(); }
  void add_move(int x, int y, double time_s) { stamps_.push_back({-1, false, x, y, time_s}); }
  void add_button(int button, bool pressed, double time_s) {
    stamps_.push_back({button, pressed, 0, 0, time_s});
  }
  // A wheel click (X11 buttons 4-7, which GLFW reports as scrolling).
  void add_wheel(double time_s) { stamps_.push_back({kWheel, true, 0, 0, time_s}); }
  // The time of the first scanned event like this one, dropping it and the events before it
  // (which GLFW did not deliver); none if there is no such event (it came after the scan).
  std::optional<double> move(double x, double y);
  std::optional<double> button(int button, bool pressed);
  std::optional<double> wheel();
  std::size_t size() const { return stamps_.size(); }

 private:
  static constexpr int kWheel = -2;
  struct Stamp {
    int button;  // -1: a move, kWheel: a wheel click
    bool pressed;
    int x, y;
    double time_s;
  };
  template <typename Match>
  std::optional<double> take(Match match);
  std::vector<Stamp> stamps_;
};

// The scan on X11; does nothing where GLFW is not on X11 (every time is then the callback's).
class PointerServerTimes {
 public:
  explicit PointerServerTimes(GLFWwindow* window);
  // Before glfwPollEvents: the times of the mouse events waiting for the window.
  void scan();
  // In a callback: the event's server time, or the time now when it has none.
  double move_time(double x, double y);
  double button_time(int glfw_button, bool pressed);
  double wheel_time();
  // Events that had a server time, and events that did not, since construction.
  std::uint64_t matched() const { return matched_; }
  std::uint64_t unmatched() const { return unmatched_; }

 private:
  GLFWwindow* window_;
  ServerTimeMatcher matcher_;
  std::uint64_t matched_ = 0, unmatched_ = 0;
};

}  // namespace impasto::app::window
