// A real tablet capture (HID reports) decoded and painted: the path live tablet input takes.
#include <gtest/gtest.h>

#include <impasto/input/hid_capture.hpp>
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/stroke_events.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "impasto/session/replay.hpp"

namespace impasto::session {
namespace {

const std::filesystem::path kCapture = std::filesystem::path(IMPASTO_TEST_FILES_DIR) /
                                       "hid/wacom_penpartner__056A_0061.hid-recorder.txt";

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

// An Ugee M708 v2 as its owner recorded it with usbhid-dump (the pressure stream), with its
// UC-Logic handshake: decoded through the vendor protocol and painted.
input::StrokeFile ugee_capture_as_strokes() {
  namespace hid = input::hid;
  const std::string dir = std::string(IMPASTO_TEST_FILES_DIR) + "/hid/captures/Ugee_M708_v2/";
  std::ifstream probe(dir + "probe.txt");
  hid::HidRecording capture;
  capture.descriptor = hid::read_descriptor_file(dir + "rd/original1.txt").bytes;
  capture.vendor_id = 0x28BD;
  capture.product_id = 0x0907;
  capture.init = hid::parse_string_probe(
      std::string(std::istreambuf_iterator<char>(probe), std::istreambuf_iterator<char>()),
      "probe.txt");
  capture.reports = hid::read_report_file(dir + "dumps/pen_pressure.txt").reports;
  input::StrokeFile file;
  for (const auto& sample : hid::decode_recording(capture)) {
    file.events.push_back(input::SampleEvent{sample});
  }
  return file;
}

TEST(HidReplay, UgeeUsbhidDumpCapturePaintsConservedFiniteStrokes) {
  const auto file = ugee_capture_as_strokes();
  ASSERT_GT(file.events.size(), 2000u);
  ReplayReport report;
  const auto painting = replay(file, tablet_canvas(0), &report);
  EXPECT_GT(report.strokes, 0u);
  EXPECT_GT(painting.canvas_totals().volume, 0.0);
  EXPECT_EQ(painting.nonfinite_count(), 0u);
  const double loaded = painting.loaded_totals().volume;
  const double kept = painting.canvas_totals().volume + painting.brush_totals().volume;
  EXPECT_NEAR(kept, loaded - painting.wiped_totals().volume, 1e-5 * loaded);
}

}  // namespace
}  // namespace impasto::session
