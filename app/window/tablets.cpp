#include "window/tablets.hpp"

#include <chrono>
#include <exception>
#include <vector>

namespace impasto::app::window {

Tablets::Tablets(double session_clock_s, WindowState& state) {
  if (!input::hid::hid_available()) return;
  try {
    manager_ = std::make_unique<input::hid::TabletManager>();
    // Tablet times count from the manager's origin (steady clock); the session's from the
    // window's. Read both clocks now and the origin's age moves one onto the other.
    const double origin_age_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - manager_->origin())
            .count();
    time_offset_s_ = session_clock_s - origin_age_s;
  } catch (const std::exception& e) {
    state.tablet_error = e.what();
  }
}

void Tablets::poll(WindowState& state, const std::function<TabletTargetGeometry()>& geometry,
                   session::PenFeed& feed, double now_s) {
  if (!manager_) return;
  state.tablets = manager_->tablets();
  const std::vector<input::hid::TabletSamples> polled = manager_->poll_tablets();
  if (polled.empty()) return;
  const TabletTargetGeometry where = geometry();
  if (where.canvas_w_cells == 0) return;
  seen_s_ = now_s;
  paintcore::PenSample newest;
  const std::size_t fed = feed_tablet_samples(polled, time_offset_s_, state.tablet, where, feed,
                                              &state.tablet_error, &newest);
  state.tablet_samples += fed;
  if (fed > 0) newest_ = newest;
}

}  // namespace impasto::app::window
