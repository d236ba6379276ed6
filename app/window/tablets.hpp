#pragma once
// The pen tablets the window paints with: read on their own threads (input::hid::TabletManager),
// polled once a frame into the pen feed through the canvas view (tablet_input.hpp). Optional:
// without hidapi or without a tablet the mouse paints alone.
#include <impasto/input/hid_device.hpp>

#include <functional>
#include <memory>
#include <optional>

#include "impasto/session/pen_feed.hpp"
#include "window/tablet_input.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class Tablets {
 public:
  // `session_clock_s`: the window's session clock now (the tablets' times are moved onto it).
  // A failure to start is said in state.tablet_error.
  Tablets(double session_clock_s, WindowState& state);
  // The tablets' samples since the last poll, fed as pen samples mapped through the window's
  // geometry (asked for only when samples came); state lists the tablets and counts them.
  void poll(WindowState& state, const std::function<TabletTargetGeometry()>& geometry,
            session::PenFeed& feed, double now_s);
  // A tablet sent a sample within the last quarter second (its pen is near: the outline
  // follows it, not the mouse).
  bool near(double now_s) const { return now_s - seen_s_ < 0.25; }
  // The newest sample a near pen sent (canvas mm, with its pressure, tilt and rotation),
  // hovering or pressed; nullptr when no pen is near or it left the tablet's range.
  const paintcore::PenSample* pen(double now_s) const {
    return near(now_s) && newest_ && (newest_->buttons & paintcore::kPenInRange) ? &*newest_
                                                                                 : nullptr;
  }

 private:
  std::unique_ptr<input::hid::TabletManager> manager_;
  double time_offset_s_ = 0.0;  // tablet clock -> session clock
  double seen_s_ = -1e9;        // when a tablet last sent a sample
  std::optional<paintcore::PenSample> newest_;
};

}  // namespace impasto::app::window
