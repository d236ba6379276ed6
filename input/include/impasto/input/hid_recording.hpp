#pragma once
// Files of HID data: report descriptors (raw .bin, hex text, or a hid-recorder capture's
// "R:" line) and input reports (a hid-recorder capture's "E:" lines, or hex lines).
#include <impasto/input/hid_descriptor.hpp>
#include <impasto/input/hid_init_exchange.hpp>
#include <impasto/paintcore/pen_sample.hpp>

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace impasto::input::hid {

struct RecordedReport {
  double time_s = 0.0;
  std::vector<std::uint8_t> bytes;
  bool operator==(const RecordedReport&) const = default;
};

// A capture in the format of hid-recorder (hid-tools): "R: N bytes…" the descriptor,
// "N: name", "P: phys", "I: bus vendor product" (hex), "E: sec.usec N bytes…" one report.
// Impasto adds the handshake (hid_init_exchange.hpp): "S: index N bytes…" a string
// descriptor read, "F: N bytes…" a feature report read, "O: N bytes…" an output report sent.
struct HidRecording {
  std::string name;
  std::string phys;
  std::uint32_t bus = 0;
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::vector<std::uint8_t> descriptor;
  std::vector<RecordedReport> reports;
  InitExchange init;
  bool operator==(const HidRecording&) const = default;
};

// Hex bytes separated by blanks or commas ("05 0d", "0x05,0x0d"). Errors name the line.
std::vector<std::uint8_t> parse_hex_bytes(const std::string& text, const std::string& source,
                                          int line);

// One "E:" line's content after the tag: "seconds count bytes...".
RecordedReport parse_recorder_event(const std::string& rest, const std::string& source, int line);

HidRecording parse_hid_recording(std::istream& in, const std::string& source);
HidRecording read_hid_recording(const std::filesystem::path& path);
void write_hid_recording(std::ostream& out, const HidRecording& recording);
// One "E:" line for a report (without the newline).
std::string recorder_event_line(const RecordedReport& report);

// A descriptor from a .bin file (raw bytes), a hid-recorder capture ("R:" line), a
// usbhid-dump file or hex text (hid_capture.hpp's read_descriptor_file says which).
std::vector<std::uint8_t> load_descriptor_bytes(const std::filesystem::path& path);

// Reports from a hid-recorder capture ("E:" lines, with their times), a usbhid-dump stream
// or hex lines (one report a line, `#` comments; times are 0). See read_report_file.
std::vector<RecordedReport> load_reports(const std::filesystem::path& path);

// Every pen sample of a capture, in order: the one call a replay needs. Reports that are not
// pen reports are skipped. Tablets with a known vendor protocol are decoded by it (see
// hid_vendor.hpp); others need standard pen reports, else UnsupportedTablet is thrown.
// Positions are mm on the tablet (map them onto the canvas with AreaMapping), times are the
// capture's seconds.
std::vector<paintcore::PenSample> decode_recording(const HidRecording& recording);
std::vector<paintcore::PenSample> decode_recording(const std::filesystem::path& path);

}  // namespace impasto::input::hid
