#include "window/pointer_gestures.hpp"

#include <algorithm>
#include <cmath>

namespace impasto::app::window {

void PointerGestures::press(const PointerEvent& event, const PointerFrame& frame) {
  if (drag_ != Drag::kNone) return;  // one drag at a time; its own button ends it
  if (frame.canvas_at && !frame.canvas_at(event.x, event.y)) return;  // the panels' press
  Drag drag = Drag::kNone;
  if (event.button == kLeftButton) {
    if (frame.space_down) {
      drag = Drag::kPan;
    } else if (!frame.tablet_near) {
      drag = Drag::kPaint;
    }
  } else if (event.button == kMiddleButton) {
    drag = Drag::kPan;
  } else if (event.button == kRightButton) {
    drag = Drag::kRotate;
  }
  if (drag == Drag::kNone) return;
  drag_ = drag;
  drag_button_ = event.button;
  if (drag_ == Drag::kPaint && handlers_.paint) handlers_.paint(event, true);
}

void PointerGestures::apply(std::span<const PointerEvent> events, const PointerFrame& frame) {
  for (const PointerEvent& event : events) {
    switch (event.action) {
      case PointerAction::kPress:
        press(event, frame);
        break;
      case PointerAction::kMove:
        if (drag_ == Drag::kPaint && handlers_.paint) handlers_.paint(event, true);
        if (drag_ == Drag::kPan && handlers_.pan) {
          handlers_.pan(last_x_, last_y_, event.x, event.y, event.time_s);
        }
        if (drag_ == Drag::kRotate && handlers_.rotate) {
          handlers_.rotate(last_x_, last_y_, event.x, event.y, event.time_s);
        }
        break;
      case PointerAction::kRelease:
        if (event.button != drag_button_) break;
        if (drag_ == Drag::kPaint && handlers_.paint) handlers_.paint(event, false);
        drag_ = Drag::kNone;
        drag_button_ = -1;
        break;
    }
    last_x_ = event.x;
    last_y_ = event.y;
  }
}

float SpeedPressure::at(double x_mm, double y_mm, double time_s) {
  constexpr double kWindowS = 0.05;    // speed over the last 50 ms
  constexpr double kMinSpanS = 0.004;  // shorter spans keep the last speed
  double path = 0.0;
  if (!recent_.empty()) {
    const Sample& last = recent_.back();
    path = last.path_mm + std::hypot(x_mm - last.x_mm, y_mm - last.y_mm);
  }
  recent_.push_back({x_mm, y_mm, time_s, path});
  // Keep the newest sample at least kWindowS old, so the span covers the whole window.
  while (recent_.size() > 2 && time_s - recent_[1].time_s >= kWindowS) recent_.pop_front();
  const Sample& oldest = recent_.front();
  const double span = time_s - oldest.time_s;
  if (span >= kMinSpanS) speed_mm_s_ = (path - oldest.path_mm) / span;
  // Fast strokes press lightly: full pressure at rest, a fifth at 300 mm/s.
  return static_cast<float>(std::clamp(1.0 - speed_mm_s_ / 375.0, 0.2, 1.0));
}

}  // namespace impasto::app::window
