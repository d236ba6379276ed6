// The Wacom PenPartner capture: every report decodes to the usage values an independent
// parser (hid-tools) gave, and the pen samples follow the tablet's protocol.
#include <impasto/input/hid_recording.hpp>
#include <impasto/input/hid_report.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace impasto::input::hid {
namespace {

const std::string kCapture =
    IMPASTO_TEST_FILES_DIR "/hid/wacom_penpartner__056A_0061.hid-recorder.txt";
const std::string kDecoded = IMPASTO_TEST_FILES_DIR "/hid/wacom_penpartner__056A_0061.decoded.tsv";

struct ReferenceRow {
  double time_s;
  std::string hex;
  std::string usages;  // "name=value;name=value"
};

std::vector<ReferenceRow> reference_rows() {
  std::ifstream in(kDecoded);
  std::vector<ReferenceRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    ReferenceRow row;
    std::string time;
    std::getline(fields, time, '\t');
    std::getline(fields, row.hex, '\t');
    std::getline(fields, row.usages);
    row.time_s = std::stod(time);
    rows.push_back(row);
  }
  return rows;
}

TEST(PenPartnerCapture, HeaderAndCounts) {
  const HidRecording capture = read_hid_recording(kCapture);
  EXPECT_EQ(capture.name, "WACOM FT-0203-UV1.4-2");
  EXPECT_EQ(capture.bus, 3u);
  EXPECT_EQ(capture.vendor_id, 0x056A);
  EXPECT_EQ(capture.product_id, 0x0061);
  EXPECT_EQ(capture.descriptor.size(), 110u);
  EXPECT_EQ(capture.reports.size(), 874u);
}

TEST(PenPartnerCapture, EveryReportMatchesTheIndependentDecoder) {
  const HidRecording capture = read_hid_recording(kCapture);
  const ReportDescriptor d = parse_report_descriptor(capture.descriptor, kCapture);
  const std::vector<ReferenceRow> rows = reference_rows();
  ASSERT_EQ(rows.size(), capture.reports.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RecordedReport& report = capture.reports[i];
    EXPECT_NEAR(report.time_s, rows[i].time_s, 1e-9) << "report " << i;
    EXPECT_EQ(report.bytes, parse_hex_bytes(rows[i].hex, kDecoded, static_cast<int>(i) + 2));
    std::string ours;
    for (const UsageValue& v : decode_usage_values(d, report.bytes)) {
      if (!ours.empty()) ours += ';';
      ours += usage_name(v.usage) + "=" + std::to_string(v.value);
    }
    ASSERT_EQ(ours, rows[i].usages) << "report " << i << " (" << rows[i].hex << ")";
  }
}

TEST(PenPartnerCapture, DecodesToPenSamples) {
  const std::vector<paintcore::PenSample> samples = decode_recording(kCapture);
  const HidRecording capture = read_hid_recording(kCapture);
  std::size_t pen_reports = 0;
  for (const RecordedReport& r : capture.reports) pen_reports += r.bytes.at(0) == 2 ? 1 : 0;
  ASSERT_EQ(samples.size(), pen_reports);
  // E: 0.067830 8 02 90 e0 04 4c 04 00 00: in range, x 0x04e0, y 0x044c at 50 lines per mm.
  const paintcore::PenSample& first = samples.front();
  EXPECT_DOUBLE_EQ(first.time_s, 0.067830);
  EXPECT_DOUBLE_EQ(first.x_mm, 0x04e0 / 50.0);
  EXPECT_DOUBLE_EQ(first.y_mm, 0x044c / 50.0);
  EXPECT_EQ(first.pressure, 0.0f);
  EXPECT_EQ(first.buttons, paintcore::kPenInRange);
  // Status 0x91 is the tip down, 0x94 the second side button; 0x10 is out of range.
  std::size_t tip = 0, barrel2 = 0, out_of_range = 0, strokes = 0;
  bool down = false;
  for (const paintcore::PenSample& s : samples) {
    tip += s.tip_down() ? 1 : 0;
    barrel2 += (s.buttons & paintcore::kPenBarrel2) ? 1 : 0;
    out_of_range += (s.buttons & paintcore::kPenInRange) ? 0 : 1;
    strokes += (s.tip_down() && !down) ? 1 : 0;
    down = s.tip_down();
    EXPECT_GE(s.pressure, 0.0f);
    EXPECT_LE(s.pressure, 1.0f);
  }
  EXPECT_EQ(tip, 22u + 16u);         // status 0x91 and 0x95
  EXPECT_EQ(barrel2, 105u + 16u);    // status 0x94 and 0x95
  EXPECT_EQ(out_of_range, 9u + 2u);  // status 0x10 and 0x00
  EXPECT_GT(strokes, 0u);
}

TEST(HidRecordingFormat, WriteThenReadIsIdentical) {
  HidRecording capture;
  capture.name = "Test Tablet";
  capture.phys = "usb-1/input0";
  capture.bus = 3;
  capture.vendor_id = 0x256C;
  capture.product_id = 0x006D;
  capture.descriptor = {0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0xC0};
  capture.reports = {{0.0, {0x0A, 0x00}}, {0.125, {0x0A, 0xFF}}, {1.5, {}}};
  std::stringstream text;
  write_hid_recording(text, capture);
  EXPECT_EQ(parse_hid_recording(text, "memory"), capture);
}

TEST(HidRecordingFormat, ErrorsNameFileLineAndField) {
  const auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      parse_hid_recording(in, "cap.txt");
    } catch (const InputFormatError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("R: 3 05 0d\n"), "cap.txt:1: field 'R': declares 3 bytes but lists 2");
  EXPECT_EQ(error_of("R: 1 05\nE: 0.1 2 0a zz\n"),
            "cap.txt:2: field 'byte 2': expected two hex digits, found 'zz'");
  EXPECT_EQ(error_of("R: 1 05\nE: nan 1 0a\n"),
            "cap.txt:2: field 'time': 'nan' is not a finite number");
  EXPECT_EQ(error_of("N: no descriptor\n"), "cap.txt: field 'R': no descriptor ('R:' line)");
  EXPECT_EQ(error_of("R: 1 05\nI: 3 056a\n"),
            "cap.txt:2: field 'I': expected 'I: bus vendor product' in hex");
  EXPECT_EQ(error_of("R: 1 05\ngarbage\n"), "cap.txt:2: expected a 'X: ...' record");
}

TEST(HidRecordingFormat, HexBytes) {
  EXPECT_EQ(parse_hex_bytes("05 0d,0x09 0X02", "x", 1),
            (std::vector<std::uint8_t>{0x05, 0x0D, 0x09, 0x02}));
  EXPECT_THROW(parse_hex_bytes("5 0d", "x", 1), InputFormatError);
  EXPECT_THROW(parse_hex_bytes("050d", "x", 1), InputFormatError);
}

}  // namespace
}  // namespace impasto::input::hid
