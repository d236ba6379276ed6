#pragma once
// The one path from a pen to the simulation, shared by the mouse and the tablets: samples
// in canvas mm become session events (recorded to the session's stroke file by SimWorker).
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/pen_sample.hpp>

#include <functional>

namespace impasto::session {

class PenFeed {
 public:
  using EventSink = std::function<void(input::StrokeEvent)>;
  explicit PenFeed(EventSink sink) : sink_(std::move(sink)) {}

  // Tip-down samples, and the first tip-up sample after them (the stroke's end), go to the
  // sink; hovering samples do not (they would only bloat the recording). Times are made
  // non-decreasing, as stroke files require, when several sources take turns.
  void feed(paintcore::PenSample sample);
  bool in_stroke() const { return in_stroke_; }
  // Samples passed on since construction.
  std::size_t fed() const { return fed_; }

 private:
  EventSink sink_;
  bool in_stroke_ = false;
  double last_time_s_ = 0.0;
  std::size_t fed_ = 0;
};

}  // namespace impasto::session
