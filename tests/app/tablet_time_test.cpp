// Tablet samples keep their own times on the way to the simulation: each report's time
// (stamped by its reader thread) moves onto the session clock unchanged, and two tablets'
// samples polled in one frame are fed oldest first, so session::PenFeed never holds a time back.
#include <gtest/gtest.h>

#include <variant>
#include <vector>

#include "impasto/session/pen_feed.hpp"
#include "window/tablet_input.hpp"

namespace impasto::app::window {
namespace {

input::hid::TabletSamples tablet_with(const std::string& name, std::vector<double> times) {
  input::hid::TabletSamples polled;
  polled.tablet.name = name;
  polled.tablet.area = {100.0, 100.0, true};
  for (double t : times) {
    paintcore::PenSample s;
    s.time_s = t;
    s.x_mm = 10.0 * t;  // where each sample is tells which one it was
    s.y_mm = name == "a" ? 10.0 : 20.0;
    s.pressure = 0.5f;
    s.buttons = paintcore::kPenTip | paintcore::kPenInRange;
    polled.samples.push_back(s);
  }
  return polled;
}

TEST(TabletTime, SamplesOfTwoTabletsAreFedOldestFirstWithTheirOwnTimes) {
  const std::vector<input::hid::TabletSamples> polled = {tablet_with("a", {1.0, 1.2, 1.4}),
                                                         tablet_with("b", {1.1, 1.3})};
  TabletSettings settings;
  settings.target = TabletTarget::kCanvas;
  settings.keep_aspect = false;
  TabletTargetGeometry geometry;
  geometry.canvas_w_cells = geometry.canvas_h_cells = 1000;
  geometry.cell_mm = 0.1;  // a 100 mm canvas: tablet mm are canvas mm
  std::vector<paintcore::PenSample> fed;
  session::PenFeed feed(
      [&](input::StrokeEvent e) { fed.push_back(std::get<input::SampleEvent>(e).sample); });
  const double offset_s = 5.0;
  ASSERT_EQ(feed_tablet_samples(polled, offset_s, settings, geometry, feed), 5u);
  ASSERT_EQ(fed.size(), 5u);
  const double expected[] = {1.0, 1.1, 1.2, 1.3, 1.4};
  for (std::size_t i = 0; i < fed.size(); ++i) {
    EXPECT_DOUBLE_EQ(fed[i].time_s, expected[i] + offset_s) << i;
    EXPECT_NEAR(fed[i].x_mm, 10.0 * expected[i], 1e-9) << i;  // the sample of that time
  }
}

}  // namespace
}  // namespace impasto::app::window
