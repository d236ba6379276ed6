// A real tablet capture (HID reports) decoded and painted: the path live tablet input takes.
#include <gtest/gtest.h>

#include <impasto/input/hid_recording.hpp>
#include <impasto/input/stroke_events.hpp>

#include <algorithm>
#include <filesystem>

#include "session/replay.hpp"

namespace impasto::app {
namespace {

const std::filesystem::path kCapture = std::filesystem::path(IMPASTO_TEST_FILES_DIR) / "hid/wacom_penpartner__056A_0061.hid-recorder.txt";

input::StrokeFile capture_as_strokes() {
  input::StrokeFile file;
  for (const auto& sample : input::hid::decode_recording(kCapture)) {
    file.events.push_back(input::SampleEvent{sample});
  }
  return file;
}

ReplayOptions tablet_canvas(int threads) {
  ReplayOptions options;  // tablet mm map 1:1 onto a 160 x 120 mm canvas at 100 dpi
  options.width_cells = 630;
  options.height_cells = 473;
  options.dpi = 100;
  options.threads = threads;
  options.default_brush.size_mm = 3.0;
  return options;
}

TEST(HidReplay, PenPartnerCapturePaintsConservedFiniteStrokes) {
  const auto file = capture_as_strokes();
  ASSERT_GT(file.events.size(), 100u);
  ReplayReport report;
  const auto painting = replay(file, tablet_canvas(0), &report);
  EXPECT_GT(report.strokes, 0u);
  EXPECT_GT(painting.steps(), 0u);
  EXPECT_GT(painting.canvas_totals().volume, 0.0);
  EXPECT_EQ(painting.nonfinite_count(), 0u);
  const double loaded = painting.loaded_totals().volume;
  const double kept = painting.canvas_totals().volume + painting.brush_totals().volume;
  EXPECT_NEAR(kept, loaded - painting.wiped_totals().volume, 1e-5 * loaded);
}

TEST(HidReplay, SameCaptureSamePaintingForAnyThreadCount) {
  const auto file = capture_as_strokes();
  EXPECT_EQ(replay(file, tablet_canvas(1)).state_hash(),
            replay(file, tablet_canvas(2)).state_hash());
}

}  // namespace
}  // namespace impasto::app
