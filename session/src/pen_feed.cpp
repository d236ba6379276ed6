#include "impasto/session/pen_feed.hpp"

#include <algorithm>

namespace impasto::session {

void PenFeed::feed(paintcore::PenSample sample) {
  if (!sample.tip_down() && !in_stroke_) return;  // hovering
  in_stroke_ = sample.tip_down();
  if (!in_stroke_) sample.pressure = 0.0f;
  sample.time_s = std::max(sample.time_s, last_time_s_);
  last_time_s_ = sample.time_s;
  ++fed_;
  sink_(input::SampleEvent{sample});
}

}  // namespace impasto::session
