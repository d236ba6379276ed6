#pragma once
// The files tablet owners send: report descriptors and report streams as raw bytes, hex
// text, hid-recorder captures (hid-tools) or usbhid-dump output, and the string descriptors
// a vendor handshake reads. Each reader says which format it found.
#include <impasto/input/hid_init_exchange.hpp>
#include <impasto/input/hid_recording.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::input::hid {

enum class CaptureFormat {
  kRawBinary,    // the bytes themselves (a .bin descriptor)
  kHexText,      // hex bytes; for reports, one report a line
  kHidRecorder,  // hid-recorder: "R:", "E:", ... lines
  kUsbhidDump,   // usbhid-dump: "BUS:DEV:IFACE:DESCRIPTOR|STREAM time" then hex lines
  kStringProbe,  // string descriptors as "S <index> <bytes>" lines (DIGImend probe output)
};
const char* capture_format_name(CaptureFormat format);

// The format of a file's contents; `binary_name` when its name ends in .bin.
CaptureFormat detect_capture_format(std::string_view text, bool binary_name);

// One usbhid-dump record: a descriptor or a report of one interface.
struct UsbhidDumpRecord {
  int bus = 0;
  int device = 0;
  int interface = 0;
  bool descriptor = false;  // DESCRIPTOR, else STREAM
  double time_s = 0.0;      // as printed (seconds since the epoch)
  std::vector<std::uint8_t> bytes;
  int line = 0;  // of its header
};

// A whole usbhid-dump file. Damaged records (a header or hex line that does not read, such
// as a write torn by NUL bytes) are skipped with a warning naming their line; `warnings`
// lists them.
struct UsbhidDump {
  std::vector<UsbhidDumpRecord> records;
  std::vector<std::string> warnings;
};
UsbhidDump parse_usbhid_dump(std::string_view text, const std::string& source);

struct DescriptorFile {
  std::vector<std::uint8_t> bytes;
  CaptureFormat format = CaptureFormat::kRawBinary;
  int interface = -1;  // usbhid-dump: the interface it belongs to
  std::vector<std::string> warnings;
};
// A descriptor in any of the formats. A usbhid-dump file holding several interfaces' needs
// `interface`; the error lists them.
DescriptorFile read_descriptor_file(const std::filesystem::path& path,
                                    std::optional<int> interface = std::nullopt);

struct ReportFile {
  std::vector<RecordedReport> reports;
  CaptureFormat format = CaptureFormat::kHexText;
  std::vector<int> interfaces;  // usbhid-dump: those present (before filtering)
  std::vector<std::string> warnings;
};
// Reports in any text format. usbhid-dump times are made relative to its first record;
// `interface` keeps one interface's reports.
ReportFile read_report_file(const std::filesystem::path& path,
                            std::optional<int> interface = std::nullopt);

}  // namespace impasto::input::hid
