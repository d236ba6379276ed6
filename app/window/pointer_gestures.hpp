#pragma once
// What the mouse does on the canvas, event by event: the left button paints (or pans with
// Space held), the middle button pans, the right button rotates. Whether a press belongs to
// the canvas or to the panels is decided where the press happened, and the drag it starts
// keeps every move until that button is released, so a release, a move and a press within
// one frame make two strokes with nothing between them.
#include <deque>
#include <functional>
#include <span>

#include "window/pointer_events.hpp"

namespace impasto::app::window {

// What the frame knows besides its events.
struct PointerFrame {
  bool space_down = false;   // Space held: the left button pans instead of painting
  bool tablet_near = false;  // a tablet's pen is near: it paints, the mouse does not
  // Whether a press at this window position goes to the canvas (not to a panel or popup).
  std::function<bool(double x, double y)> canvas_at;
};

struct PointerHandlers {
  // A pen sample at the event's position and time; tip_down false ends the stroke.
  std::function<void(const PointerEvent& at, bool tip_down)> paint;
  // Drags from one window position to the next, by a move at time_s (its event's own time).
  using Drag =
      std::function<void(double from_x, double from_y, double to_x, double to_y, double time_s)>;
  Drag pan;
  Drag rotate;
};

class PointerGestures {
 public:
  explicit PointerGestures(PointerHandlers handlers) : handlers_(std::move(handlers)) {}

  // Applies the events in order.
  void apply(std::span<const PointerEvent> events, const PointerFrame& frame);
  bool painting() const { return drag_ == Drag::kPaint; }

 private:
  enum class Drag { kNone, kPaint, kPan, kRotate };
  void press(const PointerEvent& event, const PointerFrame& frame);

  PointerHandlers handlers_;
  Drag drag_ = Drag::kNone;
  int drag_button_ = -1;
  double last_x_ = 0, last_y_ = 0;
};

// Pressure from speed for a mouse: full at rest, a fifth at 300 mm/s. The speed is the path
// over the last 50 ms of samples by their own times, so a burst of samples that reached the
// window together does not read as infinitely fast.
class SpeedPressure {
 public:
  void start_stroke() {
    recent_.clear();
    speed_mm_s_ = 0.0;
  }
  float at(double x_mm, double y_mm, double time_s);
  double speed_mm_s() const { return speed_mm_s_; }

 private:
  struct Sample {
    double x_mm, y_mm, time_s, path_mm;  // path: length of the stroke up to here
  };
  std::deque<Sample> recent_;
  double speed_mm_s_ = 0.0;
};

}  // namespace impasto::app::window
