#include "window/pointer_server_times.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#if IMPASTO_HAVE_X11
#include <X11/Xlib.h>
// GLFW's native access (glfw3native.h would also want the Xrandr headers).
extern "C" {
Display* glfwGetX11Display(void);
::Window glfwGetX11Window(GLFWwindow* window);
}
#endif

#include <chrono>
#include <cmath>

namespace impasto::app::window {

std::optional<double> server_time_on_glfw_clock(std::uint32_t server_ms, double mono_now_s,
                                                double glfw_now_s, double max_age_s) {
  // The age in whole ms, modulo 2^32 as the server's clock wraps, plus the fraction of the
  // current ms the server's clock does not show.
  const double now_ms = std::floor(mono_now_s * 1e3);
  const auto now_wrapped = static_cast<std::uint32_t>(std::fmod(now_ms, 4294967296.0));
  const auto age_ms = static_cast<std::int32_t>(now_wrapped - server_ms);
  const double age_s = (age_ms + (mono_now_s * 1e3 - now_ms)) * 1e-3;
  if (age_ms < 0 || age_s > max_age_s) return std::nullopt;
  return glfw_now_s - age_s;
}

template <typename Match>
std::optional<double> ServerTimeMatcher::take(Match match) {
  for (std::size_t i = 0; i < stamps_.size(); ++i) {
    if (!match(stamps_[i])) continue;
    const double time_s = stamps_[i].time_s;
    stamps_.erase(stamps_.begin(), stamps_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    return time_s;
  }
  return std::nullopt;
}

std::optional<double> ServerTimeMatcher::move(double x, double y) {
  return take([&](const Stamp& s) { return s.button < 0 && s.x == x && s.y == y; });
}

std::optional<double> ServerTimeMatcher::button(int button, bool pressed) {
  return take([&](const Stamp& s) { return s.button == button && s.pressed == pressed; });
}

std::optional<double> ServerTimeMatcher::wheel() {
  return take([](const Stamp& s) { return s.button == kWheel; });
}

PointerServerTimes::PointerServerTimes(GLFWwindow* window) : window_(window) {}

#if IMPASTO_HAVE_X11
namespace {

// X11 button numbers as GLFW maps them: 1 left, 2 middle, 3 right, 4-7 the wheel, 8 and up
// the further buttons.
int glfw_button_of(unsigned x_button) {
  if (x_button == Button1) return GLFW_MOUSE_BUTTON_LEFT;
  if (x_button == Button2) return GLFW_MOUSE_BUTTON_MIDDLE;
  if (x_button == Button3) return GLFW_MOUSE_BUTTON_RIGHT;
  if (x_button >= 8) return static_cast<int>(x_button) - 8 + GLFW_MOUSE_BUTTON_4;
  return -1;  // the wheel: GLFW reports it as scrolling
}

struct ScanContext {
  ::Window window;
  ServerTimeMatcher* matcher;
  double mono_now_s, glfw_now_s;
};

// Xlib calls this for each queued event; it records and never takes one out of the queue.
Bool record_event(Display*, XEvent* event, XPointer arg) {
  auto& scan = *reinterpret_cast<ScanContext*>(arg);
  if (event->xany.window != scan.window) return False;
  const auto on_glfw_clock = [&](::Time time) {
    return server_time_on_glfw_clock(static_cast<std::uint32_t>(time), scan.mono_now_s,
                                     scan.glfw_now_s);
  };
  if (event->type == MotionNotify) {
    if (const auto t = on_glfw_clock(event->xmotion.time)) {
      scan.matcher->add_move(event->xmotion.x, event->xmotion.y, *t);
    }
  } else if (event->type == ButtonPress || event->type == ButtonRelease) {
    const int button = glfw_button_of(event->xbutton.button);
    const auto t = on_glfw_clock(event->xbutton.time);
    if (button >= 0 && t) scan.matcher->add_button(button, event->type == ButtonPress, *t);
    if (button < 0 && event->type == ButtonPress && t) scan.matcher->add_wheel(*t);
  }
  return False;
}

}  // namespace

void PointerServerTimes::scan() {
  matcher_.clear();
  Display* display = glfwGetX11Display();
  if (!display) return;  // not on X11
  ScanContext context{glfwGetX11Window(window_), &matcher_, 0.0, 0.0};
  // Both clocks read together; steady_clock is CLOCK_MONOTONIC, as the X server's clock.
  context.mono_now_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  context.glfw_now_s = glfwGetTime();
  XEvent unused;
  XCheckIfEvent(display, &unused, record_event, reinterpret_cast<XPointer>(&context));
}
#else
void PointerServerTimes::scan() {}
#endif

double PointerServerTimes::move_time(double x, double y) {
  const auto t = matcher_.move(x, y);
  ++(t ? matched_ : unmatched_);
  return t ? *t : glfwGetTime();
}

double PointerServerTimes::button_time(int glfw_button, bool pressed) {
  const auto t = matcher_.button(glfw_button, pressed);
  ++(t ? matched_ : unmatched_);
  return t ? *t : glfwGetTime();
}

double PointerServerTimes::wheel_time() {
  const auto t = matcher_.wheel();
  ++(t ? matched_ : unmatched_);
  return t ? *t : glfwGetTime();
}

}  // namespace impasto::app::window
