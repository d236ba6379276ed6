// Tablet input as the window takes it: tablet mm mapped through the active area onto the
// screen, the window or the canvas, the pressure curve, and a recorded HID report stream fed
// through the same calls the window's frame loop makes (feed_tablet_samples -> session::PenFeed ->
// session::SimWorker, which records the session).
#include <gtest/gtest.h>

#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_tablet.hpp>
#include <impasto/input/stroke_file.hpp>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <string>

#include "impasto/session/pen_feed.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/tablet_input.hpp"

namespace impasto::app::window {
namespace {

const std::filesystem::path kCapture = std::filesystem::path(IMPASTO_TEST_FILES_DIR) /
                                       "hid/wacom_penpartner__056A_0061.hid-recorder.txt";

// A 1000 x 600 px window at (200, 100) on a 1920 x 1080 screen, showing a 400 x 300-cell
// canvas (0.25 mm cells) at 2 px a cell, turned by 30 degrees.
TabletTargetGeometry geometry() {
  TabletTargetGeometry g;
  g.screen_px = {0, 0, 1920, 1080};
  g.window_origin_px = {200, 100};
  g.window_w = 1000;
  g.window_h = 600;
  g.view = {200.0, 150.0, 2.0, 0.5235987755982988};
  g.canvas_w_cells = 400;
  g.canvas_h_cells = 300;
  g.cell_mm = 0.25;
  return g;
}

paintcore::PenSample at(double x_mm, double y_mm, float pressure = 1.0f) {
  paintcore::PenSample s;
  s.x_mm = x_mm;
  s.y_mm = y_mm;
  s.pressure = pressure;
  s.tilt_x_deg = 12.0f;
  s.buttons = paintcore::kPenTip | paintcore::kPenInRange;
  return s;
}

std::array<double, 2> canvas_mm_at_window_pixel(double x, double y) {
  const auto g = geometry();
  const auto cell = g.view.window_to_cell(x, y, g.window_w, g.window_h);
  return {cell[0] * g.cell_mm, cell[1] * g.cell_mm};
}

TEST(TabletMapping, WindowTargetMapsTabletCornersToWindowCornersThroughTheView) {
  const input::hid::TabletArea area{160.0, 120.0, true};
  TabletSettings settings;
  settings.target = TabletTarget::kWindow;
  settings.keep_aspect = false;
  for (const auto& [tx, ty, wx, wy] :
       {std::array{0.0, 0.0, 0.0, 0.0}, std::array{160.0, 120.0, 1000.0, 600.0},
        std::array{40.0, 90.0, 250.0, 450.0}}) {
    const auto mapped = map_tablet_sample(at(tx, ty), area, settings, geometry());
    const auto expected = canvas_mm_at_window_pixel(wx, wy);
    EXPECT_NEAR(mapped.x_mm, expected[0], 1e-9);
    EXPECT_NEAR(mapped.y_mm, expected[1], 1e-9);
    EXPECT_EQ(mapped.tilt_x_deg, 12.0f);  // everything but position and pressure unchanged
  }
}

TEST(TabletMapping, KeepAspectUsesTheCentredPartOfTheTablet) {
  // 160 x 120 mm onto a 1000 x 600 window (5:3): the used part is 160 x 96 mm, 12 mm down.
  const input::hid::TabletArea area{160.0, 120.0, true};
  TabletSettings settings;
  settings.target = TabletTarget::kWindow;
  const auto top_left = map_tablet_sample(at(0.0, 12.0), area, settings, geometry());
  const auto expected = canvas_mm_at_window_pixel(0.0, 0.0);
  EXPECT_NEAR(top_left.x_mm, expected[0], 1e-9);
  EXPECT_NEAR(top_left.y_mm, expected[1], 1e-9);
}

TEST(TabletMapping, ScreenTargetGoesThroughTheWindowsPlaceOnTheScreen) {
  const input::hid::TabletArea area{192.0, 108.0, true};  // 10 px per mm onto the screen
  TabletSettings settings;
  settings.target = TabletTarget::kScreen;
  // Screen pixel (200, 100) is the window's top-left corner.
  const auto mapped = map_tablet_sample(at(20.0, 10.0), area, settings, geometry());
  const auto expected = canvas_mm_at_window_pixel(0.0, 0.0);
  EXPECT_NEAR(mapped.x_mm, expected[0], 1e-9);
  EXPECT_NEAR(mapped.y_mm, expected[1], 1e-9);
}

TEST(TabletMapping, CanvasTargetIgnoresTheView) {
  const input::hid::TabletArea area{160.0, 120.0, true};
  TabletSettings settings;
  settings.target = TabletTarget::kCanvas;
  const auto centre = map_tablet_sample(at(80.0, 60.0), area, settings, geometry());
  EXPECT_NEAR(centre.x_mm, 50.0, 1e-9);  // 400 cells x 0.25 mm / 2
  EXPECT_NEAR(centre.y_mm, 37.5, 1e-9);
}

TEST(TabletMapping, PressureGoesThroughTheCurve) {
  const input::hid::TabletArea area{160.0, 120.0, true};
  TabletSettings settings;
  settings.pressure_gamma = 2.0f;
  EXPECT_NEAR(map_tablet_sample(at(1, 1, 0.5f), area, settings, geometry()).pressure, 0.25f, 1e-6);
  settings.bezier = true;
  settings.bezier_points = {0.0f, 0.0f, 1.0f, 1.0f};  // the diagonal
  EXPECT_NEAR(map_tablet_sample(at(1, 1, 0.3f), area, settings, geometry()).pressure, 0.3f, 1e-4);
}

TEST(TabletMapping, ATabletWithoutAnAreaIsAClearError) {
  EXPECT_THROW(map_tablet_sample(at(1, 1), {0.0, 0.0, false}, {}, geometry()),
               std::invalid_argument);
}

TEST(PenFeed, PassesStrokesAndTheirEndButNotHovering) {
  std::vector<input::StrokeEvent> events;
  session::PenFeed feed([&](input::StrokeEvent e) { events.push_back(std::move(e)); });
  auto hover = at(1, 1, 0.0f);
  hover.buttons = paintcore::kPenInRange;
  hover.time_s = 5.0;
  feed.feed(hover);
  auto down = at(2, 2);
  down.time_s = 4.0;  // an earlier clock (another source): kept in order
  feed.feed(down);
  feed.feed(hover);  // the stroke's end
  feed.feed(hover);
  ASSERT_EQ(events.size(), 2u);
  const auto& first = std::get<input::SampleEvent>(events[0]).sample;
  const auto& last = std::get<input::SampleEvent>(events[1]).sample;
  EXPECT_TRUE(first.tip_down());
  EXPECT_FALSE(last.tip_down());
  EXPECT_EQ(last.pressure, 0.0f);
  EXPECT_GE(last.time_s, first.time_s);
  EXPECT_FALSE(feed.in_stroke());
}

TEST(TabletFeed, RecordedReportStreamPaintsAndRecordsExactlyWhatTheWindowWould) {
  const input::hid::HidRecording recording = input::hid::read_hid_recording(kCapture);
  const input::hid::TabletDecoder decoder(recording.descriptor, recording.vendor_id,
                                          recording.product_id);
  input::hid::TabletSamples polled{{"/dev/hidraw-test", recording.name, decoder.area()},
                                   input::hid::decode_recording(recording)};
  ASSERT_GT(polled.samples.size(), 100u);
  ASSERT_GT(decoder.area().width_mm, 0.0);

  const auto dir = std::filesystem::temp_directory_path() /
                   ("impasto_tablet_feed_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto record = dir / "session.strokes";
  TabletSettings settings;
  settings.target = TabletTarget::kCanvas;
  settings.pressure_gamma = 1.5f;
  const TabletTargetGeometry g = geometry();
  std::uint64_t live_hash = 0;
  std::size_t fed = 0;
  {
    session::SessionRecording recording;
    recording.recorder = std::make_unique<input::StrokeRecorder>(record);
    session::SimWorker worker(paintcore::Painting({g.canvas_w_cells, g.canvas_h_cells, 101.6, 1}),
                              std::move(recording));
    worker.submit(input::BrushEvent{"round", 3.0, 0.5, {}});
    worker.submit(input::LoadEvent{200.0, {{"Red", 1.0}}, {}});
    session::PenFeed feed([&](input::StrokeEvent e) { worker.submit(std::move(e)); });
    // The window polls a few samples a frame: feed them in frame-sized batches.
    for (std::size_t i = 0; i < polled.samples.size(); i += 7) {
      input::hid::TabletSamples frame{polled.tablet, {}};
      for (std::size_t k = i; k < std::min(i + 7, polled.samples.size()); ++k) {
        frame.samples.push_back(polled.samples[k]);
      }
      std::string error;
      paintcore::PenSample newest;
      fed += feed_tablet_samples(std::span(&frame, 1), 2.0, settings, g, feed, &error, &newest);
      EXPECT_TRUE(error.empty()) << error;
      // The newest sample, hovering or pressed, is handed back for the brush outline.
      const paintcore::PenSample& last = frame.samples.back();
      EXPECT_EQ(newest.time_s, last.time_s + 2.0);
      EXPECT_EQ(newest.tilt_x_deg, last.tilt_x_deg);
      EXPECT_EQ(newest.buttons, last.buttons);
    }
    worker.wait_idle();
    worker.with_painting([&](const paintcore::Painting& p) {
      EXPECT_GT(p.canvas_totals().volume, 0.0) << "the tablet strokes laid no paint";
      live_hash = p.state_hash();
    });
  }
  // The recording holds the mapped samples: tip-down ones and each stroke's end.
  const input::StrokeFile file = input::read_stroke_file(record);
  std::vector<paintcore::PenSample> recorded;
  for (const auto& event : file.events) {
    if (const auto* s = std::get_if<input::SampleEvent>(&event)) recorded.push_back(s->sample);
  }
  ASSERT_EQ(recorded.size(), fed);
  std::size_t tip_down = 0;
  for (const auto& s : polled.samples) tip_down += s.tip_down();
  EXPECT_GT(tip_down, 0u);
  EXPECT_LT(fed, polled.samples.size()) << "hovering samples should not be recorded";
  EXPECT_GE(fed, tip_down);
  std::size_t r = 0;
  for (const auto& s : polled.samples) {
    if (!s.tip_down()) continue;
    while (r < recorded.size() && !recorded[r].tip_down()) ++r;
    ASSERT_LT(r, recorded.size());
    auto shifted = s;
    shifted.time_s += 2.0;
    const auto expected = map_tablet_sample(shifted, decoder.area(), settings, g);
    EXPECT_NEAR(recorded[r].x_mm, expected.x_mm, 1e-6);
    EXPECT_NEAR(recorded[r].y_mm, expected.y_mm, 1e-6);
    EXPECT_NEAR(recorded[r].pressure, expected.pressure, 1e-6);
    EXPECT_NEAR(recorded[r].time_s, expected.time_s, 1e-6);
    ++r;
  }
  // Replaying the session's recording paints the very same painting.
  EXPECT_EQ(replay(file, session::ReplayOptions{}).state_hash(), live_hash);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace impasto::app::window
