#include "window/pointer_events.hpp"

#include <algorithm>
#include <utility>

namespace impasto::app::window {

void PointerEventQueue::set_position(double x, double y) {
  x_ = x;
  y_ = y;
}

void PointerEventQueue::moved(double x, double y, double time_s) {
  set_position(x, y);
  push({PointerAction::kMove, -1, x, y, time_s});
}

void PointerEventQueue::button(int button, bool pressed, double time_s) {
  push({pressed ? PointerAction::kPress : PointerAction::kRelease, button, x_, y_, time_s});
}

void PointerEventQueue::push(PointerEvent event) {
  event.time_s = std::max(event.time_s, last_time_s_);
  last_time_s_ = event.time_s;
  events_.push_back(event);
}

std::vector<PointerEvent> PointerEventQueue::take() {
  return std::exchange(events_, {});
}

}  // namespace impasto::app::window
