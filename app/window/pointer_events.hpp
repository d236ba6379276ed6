#pragma once
// Mouse input as the window system delivers it: each cursor move and button change is kept,
// in order, with its own time (GLFW's event callbacks; the time from pointer_server_times),
// until the frame hands them all to the canvas. Polling the cursor once a frame instead would turn
// a fast circle into a polygon and join two strokes whose release and press fall in one frame.
#include <cstddef>
#include <vector>

namespace impasto::app::window {

// Mouse buttons, numbered as GLFW numbers them (GLFW_MOUSE_BUTTON_LEFT, _RIGHT, _MIDDLE).
inline constexpr int kLeftButton = 0;
inline constexpr int kRightButton = 1;
inline constexpr int kMiddleButton = 2;

enum class PointerAction { kMove, kPress, kRelease };

struct PointerEvent {
  PointerAction action = PointerAction::kMove;
  int button = -1;      // the button pressed or released; -1 for a move
  double x = 0, y = 0;  // window coordinates (y down), where the cursor was
  double time_s = 0;    // when it happened (GLFW's clock)
};

// Filled by the event callbacks, emptied once a frame. Single-threaded: GLFW calls the
// callbacks from glfwPollEvents on the thread that runs the frame.
class PointerEventQueue {
 public:
  // Where the cursor is before any move arrives (a button event carries no position).
  void set_position(double x, double y);
  void moved(double x, double y, double time_s);
  void button(int button, bool pressed, double time_s);

  // Every event since the last take, oldest first. Times never go backwards (a clock that
  // did is held at the last time).
  std::vector<PointerEvent> take();
  std::size_t size() const { return events_.size(); }

 private:
  void push(PointerEvent event);

  std::vector<PointerEvent> events_;
  double x_ = 0, y_ = 0;
  double last_time_s_ = 0;
};

}  // namespace impasto::app::window
