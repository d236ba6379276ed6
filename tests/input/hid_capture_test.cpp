// What tablet owners send: usbhid-dump descriptors and streams (real DIGImend captures of a
// Huion H610 and an Ugee M708 v2), string descriptor probes, hid-recorder captures with the
// handshake, raw and hex files. Each reader says which format it found.
#include <impasto/input/hid_capture.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hid_test_files.hpp"

namespace impasto::input::hid {
namespace {

using test::kFiles;
using test::kH610;
using test::kM708;
using test::read_text;

// The number of "STREAM" headers, counted independently of the reader.
int stream_headers(const std::string& path) {
  const std::string text = read_text(path);
  int n = 0;
  for (std::size_t at = text.find(":STREAM"); at != std::string::npos;
       at = text.find(":STREAM", at + 1)) {
    ++n;
  }
  return n;
}

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / ("impasto_hid_capture_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

TEST(CaptureFormat, EachFormatIsRecognised) {
  EXPECT_EQ(detect_capture_format(read_text(kH610 + "dumps/pen_coords.txt"), false),
            CaptureFormat::kUsbhidDump);
  EXPECT_EQ(detect_capture_format(read_text(kH610 + "rd/original0.txt"), false),
            CaptureFormat::kHexText);  // the descriptors were saved without their header
  EXPECT_EQ(detect_capture_format(read_text(kH610 + "probe.txt"), false),
            CaptureFormat::kStringProbe);
  EXPECT_EQ(detect_capture_format(
                read_text(kFiles + "wacom_penpartner__056A_0061.hid-recorder.txt"), false),
            CaptureFormat::kHidRecorder);
  EXPECT_EQ(detect_capture_format(
                read_text(kFiles + "xp_pen_deco_pro_m__28BD_0904__000E.rdesc.hex"), false),
            CaptureFormat::kHexText);
  EXPECT_EQ(detect_capture_format(std::string("\x05\x0d\x09\x02", 4), false),
            CaptureFormat::kRawBinary);
  EXPECT_EQ(detect_capture_format("05 0d", true), CaptureFormat::kRawBinary);
}

TEST(UsbhidDump, DescriptorOfTheHuionH610) {
  // The capture's descriptor files hold the hex lines of usbhid-dump's DESCRIPTOR record;
  // with the record's header line they read the same.
  const DescriptorFile hex = read_descriptor_file(kH610 + "rd/original0.txt");
  EXPECT_EQ(hex.format, CaptureFormat::kHexText);
  ASSERT_EQ(hex.bytes.size(), 16u * 11 + 3);  // eleven full lines and "02 C0 C0"
  EXPECT_EQ(hex.bytes.front(), 0x05);
  EXPECT_EQ(hex.bytes[1], 0x0D);
  EXPECT_EQ(hex.bytes.back(), 0xC0);
  const std::string dump =
      "001:003:000:DESCRIPTOR         1375962278.000000\n" + read_text(kH610 + "rd/original0.txt");
  const DescriptorFile d = read_descriptor_file(temp_file("h610_rd0.txt", dump));
  EXPECT_EQ(d.format, CaptureFormat::kUsbhidDump);
  EXPECT_EQ(d.interface, 0);
  EXPECT_EQ(d.bytes, hex.bytes);
}

TEST(UsbhidDump, EveryStreamReadsWithItsRecordCount) {
  for (const std::string& dir : {kH610, kM708}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir + "dumps")) {
      const std::string path = entry.path().string();
      if (stream_headers(path) == 0) continue;  // lsusb output, not a stream
      const ReportFile f = read_report_file(path);
      EXPECT_EQ(f.format, CaptureFormat::kUsbhidDump) << path;
      EXPECT_EQ(f.interfaces.size(), 1u) << path;
      // Every record reads, unless a warning names a damaged one.
      if (f.warnings.empty()) {
        EXPECT_EQ(static_cast<int>(f.reports.size()), stream_headers(path)) << path;
      } else {
        EXPECT_LT(static_cast<int>(f.reports.size()), stream_headers(path)) << path;
      }
      ASSERT_FALSE(f.reports.empty());
      EXPECT_EQ(f.reports.front().time_s, 0.0);
      for (std::size_t i = 1; i < f.reports.size(); ++i) {
        EXPECT_GE(f.reports[i].time_s, f.reports[i - 1].time_s) << path;
      }
    }
  }
}

TEST(UsbhidDump, ARecordTornByNulBytesIsSkippedWithAWarning) {
  // The Ugee's tilt stream starts with 65,000 NUL bytes (a real flaw) that overwrite the start
  // of its first record's header: that record is lost, the others read.
  const ReportFile f = read_report_file(kM708 + "dumps/pen_tilt.txt");
  EXPECT_EQ(f.reports.size(),
            static_cast<std::size_t>(stream_headers(kM708 + "dumps/pen_tilt.txt") - 1));
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("damaged record"), std::string::npos) << f.warnings[0];
  for (const RecordedReport& r : f.reports) EXPECT_EQ(r.bytes.size(), 10u);
}

TEST(UsbhidDump, InterfacesAreKeptApart) {
  const std::string two =
      "001:003:000:DESCRIPTOR         1.000000\n 05 01 09 02\n\n"
      "001:003:001:DESCRIPTOR         1.000000\n 05 0D 09 02\n\n"
      "001:003:001:STREAM             2.500000\n 07 A0 01 00\n\n"
      "001:003:000:STREAM             3.000000\n 09 00 01 00\n";
  const auto path = temp_file("two.txt", two);
  EXPECT_THROW(read_descriptor_file(path), InputFormatError);
  EXPECT_EQ(read_descriptor_file(path, 1).bytes,
            (std::vector<std::uint8_t>{0x05, 0x0D, 0x09, 0x02}));
  const ReportFile all = read_report_file(path);
  EXPECT_EQ(all.reports.size(), 2u);
  EXPECT_EQ(all.interfaces, (std::vector<int>{0, 1}));
  EXPECT_EQ(all.warnings.size(), 1u);  // mixed interfaces
  const ReportFile one = read_report_file(path, 0);
  ASSERT_EQ(one.reports.size(), 1u);
  EXPECT_EQ(one.reports[0].bytes[0], 0x09);
}

TEST(StringProbe, TheHuionH610Answers) {
  const InitExchange init = parse_string_probe(read_text(kH610 + "probe2.txt"), "probe2.txt");
  EXPECT_EQ(init.manufacturer, "HUION");
  EXPECT_EQ(init.product, "PenTablet");
  ASSERT_NE(init.string(0x64), nullptr);
  EXPECT_EQ(*init.string(0x64),
            (std::vector<std::uint8_t>{0x0E, 0x03, 0x40, 0x9C, 0xA8, 0x61, 0x03, 0x00, 0xFF, 0x07,
                                       0xA0, 0x0F, 0x08, 0x00}));
  EXPECT_EQ(string_descriptor_text(*init.string(0x79)), "HA60");
  EXPECT_EQ(string_descriptor_text(*init.string(0x7B)), "HK On");
}

TEST(StringProbe, UnansweredIndicesAreKept) {
  const InitExchange init = parse_string_probe(read_text(kM708 + "probe_orig.txt"), "probe");
  EXPECT_EQ(init.unanswered, (std::vector<std::uint8_t>{0xC8}));
  EXPECT_EQ(init.product, "10 inch PenTablet");
  EXPECT_THROW(parse_string_probe("S 64 0E 04 40\n", "bad"), InputFormatError);  // not type 3
  EXPECT_THROW(parse_string_probe("hello\n", "bad"), InputFormatError);
}

TEST(HidRecorder, TheHandshakeTravelsWithTheCapture) {
  HidRecording capture;
  capture.descriptor = {0x05, 0x01};
  capture.vendor_id = 0x256C;
  capture.product_id = 0x006E;
  capture.init = parse_string_probe(read_text(kH610 + "probe.txt"), "probe.txt");
  capture.init.output_reports.push_back({0x02, 0xB0, 0x04});
  capture.init.feature_reports.push_back({0x05, 0x01});
  capture.reports.push_back({0.25, {0x09, 0x01, 0x00, 0x04}});
  std::ostringstream out;
  write_hid_recording(out, capture);
  std::istringstream in(out.str());
  HidRecording back = parse_hid_recording(in, "roundtrip");
  EXPECT_EQ(back.init.strings, capture.init.strings);
  EXPECT_EQ(back.init.output_reports, capture.init.output_reports);
  EXPECT_EQ(back.init.feature_reports, capture.init.feature_reports);
  EXPECT_EQ(back.reports, capture.reports);
  EXPECT_NE(out.str().find("S: 64 14 0e 03 40 9c"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace impasto::input::hid
