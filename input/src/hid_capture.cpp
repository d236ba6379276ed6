#include <impasto/input/hid_capture.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "impasto/util/text.hpp"
#include "recording_input.hpp"
#include "text_fields.hpp"

namespace impasto::input::hid {

namespace {

constexpr std::size_t kMaxBinaryDescriptor = 64 * 1024;

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

using util::trim;

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

bool all_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// "001:003:000:STREAM             1375962278.506883" -> the record's header, if it is one.
std::optional<UsbhidDumpRecord> usbhid_dump_header(std::string_view line) {
  line = trim(line);
  if (line.size() < 14 || line[3] != ':' || line[7] != ':' || line[11] != ':') return {};
  const std::string_view bus = line.substr(0, 3), dev = line.substr(4, 3),
                         iface = line.substr(8, 3);
  if (!all_digits(bus) || !all_digits(dev) || !all_digits(iface)) return {};
  std::string_view rest = line.substr(12);
  UsbhidDumpRecord record;
  if (rest.starts_with("DESCRIPTOR")) {
    record.descriptor = true;
    rest.remove_prefix(10);
  } else if (rest.starts_with("STREAM")) {
    rest.remove_prefix(6);
  } else {
    return {};
  }
  const std::string time(trim(rest));
  if (time.empty() || time.find_first_not_of("0123456789.") != std::string::npos) return {};
  try {
    record.time_s = std::stod(time);
  } catch (const std::exception&) {
    return {};
  }
  record.bus = std::stoi(std::string(bus));
  record.device = std::stoi(std::string(dev));
  record.interface = std::stoi(std::string(iface));
  return record;
}

bool looks_like_usbhid_dump(std::string_view text) {
  for (std::string_view line : lines_of(text)) {
    if (usbhid_dump_header(line)) return true;
  }
  return false;
}

bool has_tag(std::string_view line, char tag) {
  line = trim(line);
  return line.size() >= 2 && line[0] == tag && line[1] == ':';
}

bool looks_like_recorder(std::string_view text) {
  for (std::string_view line : lines_of(text)) {
    if (has_tag(line, 'R') || has_tag(line, 'E')) return true;
  }
  return false;
}

// "S 64 0E 03 ..." with a one- or two-digit hex index.
bool is_probe_string_line(std::string_view line) {
  line = trim(line);
  if (line.size() < 4 || line[0] != 'S' || line[1] != ' ') return false;
  const std::string_view rest = trim(line.substr(2));
  const std::size_t end = rest.find_first_of(" \t");
  const std::string_view index = rest.substr(0, end);
  return !index.empty() && index.size() <= 2 &&
         std::all_of(index.begin(), index.end(), [](char c) { return hex_digit(c) >= 0; });
}

bool looks_like_probe(std::string_view text) {
  for (std::string_view line : lines_of(text)) {
    if (is_probe_string_line(line)) return true;
  }
  return false;
}

bool is_text(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u == '\n' || u == '\r' || u == '\t' || (u >= 0x20 && u < 0x7F);
  });
}

std::string read_all(const std::filesystem::path& path) {
  const auto in = detail::open_recording(path, "HID capture");
  return {std::istreambuf_iterator<char>(in->stream()), std::istreambuf_iterator<char>()};
}

std::string interface_list(const std::set<int>& interfaces) {
  std::string text;
  for (int i : interfaces) text += (text.empty() ? "" : ", ") + std::to_string(i);
  return text;
}

}  // namespace

const char* capture_format_name(CaptureFormat format) {
  switch (format) {
    case CaptureFormat::kRawBinary:
      return "raw bytes";
    case CaptureFormat::kHexText:
      return "hex text";
    case CaptureFormat::kHidRecorder:
      return "hid-recorder capture";
    case CaptureFormat::kUsbhidDump:
      return "usbhid-dump output";
    case CaptureFormat::kStringProbe:
      return "string descriptor probe";
  }
  return "unknown";
}

CaptureFormat detect_capture_format(std::string_view text, bool binary_name) {
  if (binary_name) return CaptureFormat::kRawBinary;
  if (looks_like_usbhid_dump(text)) return CaptureFormat::kUsbhidDump;
  if (looks_like_recorder(text)) return CaptureFormat::kHidRecorder;
  if (looks_like_probe(text)) return CaptureFormat::kStringProbe;
  if (!is_text(text)) return CaptureFormat::kRawBinary;
  return CaptureFormat::kHexText;
}

UsbhidDump parse_usbhid_dump(std::string_view text, const std::string& source) {
  UsbhidDump dump;
  const std::vector<std::string_view> lines = lines_of(text);
  std::optional<UsbhidDumpRecord> current;
  bool damaged = false;  // the current record (or stray lines before the next header)
  int damaged_line = 0;
  const auto finish = [&] {
    if (current && !damaged) dump.records.push_back(std::move(*current));
    if (damaged) {
      dump.warnings.push_back(source + ":" + std::to_string(damaged_line) +
                              ": a damaged record, skipped");
    }
    current.reset();
    damaged = false;
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line_number = static_cast<int>(i) + 1;
    const std::string_view line = lines[i];
    if (auto header = usbhid_dump_header(line)) {
      finish();
      header->line = line_number;
      current = std::move(*header);
      continue;
    }
    const std::string_view content = trim(line);
    if (content.empty()) continue;
    if (damaged) continue;  // the rest of a damaged record
    try {
      if (!current || !is_text(content)) throw InputFormatError(source, line_number, "", "");
      const auto bytes = parse_hex_bytes(std::string(content), source, line_number);
      current->bytes.insert(current->bytes.end(), bytes.begin(), bytes.end());
    } catch (const InputFormatError&) {
      damaged = true;
      damaged_line = line_number;
    }
  }
  finish();
  return dump;
}

std::string string_descriptor_text(const std::vector<std::uint8_t>& bytes) {
  std::string text;
  for (std::size_t i = 2; i + 1 < bytes.size(); i += 2) {
    const unsigned unit = bytes[i] | (bytes[i + 1] << 8);
    if (unit == 0) break;
    text += (unit >= 0x20 && unit < 0x7F) ? static_cast<char>(unit) : '?';
  }
  return text;
}

const std::vector<std::uint8_t>* InitExchange::string(std::uint8_t index) const {
  for (const StringDescriptor& s : strings) {
    if (s.index == index) return &s.bytes;
  }
  return nullptr;
}

InitExchange parse_string_probe(std::string_view text, const std::string& source) {
  InitExchange init;
  const std::vector<std::string_view> lines = lines_of(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line_number = static_cast<int>(i) + 1;
    const detail::LineContext where{source, line_number};
    const std::string_view line = trim(lines[i]);
    if (line.empty() || line[0] == '#') continue;
    if (line.starts_with("Failed to get string descriptor 0x")) {
      const std::string_view hex = line.substr(34, 2);
      if (hex.size() == 2 && hex_digit(hex[0]) >= 0 && hex_digit(hex[1]) >= 0) {
        init.unanswered.push_back(
            static_cast<std::uint8_t>(hex_digit(hex[0]) * 16 + hex_digit(hex[1])));
      }
      continue;
    }
    if ((line[0] == 'M' || line[0] == 'P') && (line.size() == 1 || line[1] == ' ')) {
      // The UTF-16LE bytes of the manufacturer or product string (no descriptor header).
      std::vector<std::uint8_t> bytes{0, 3};
      const auto payload = parse_hex_bytes(std::string(line.substr(1)), source, line_number);
      bytes.insert(bytes.end(), payload.begin(), payload.end());
      (line[0] == 'M' ? init.manufacturer : init.product) = string_descriptor_text(bytes);
      continue;
    }
    if (!is_probe_string_line(line)) where.fail("", "expected 'S index bytes', 'M', 'P' lines");
    const std::string_view rest = trim(line.substr(2));
    const std::size_t end = rest.find_first_of(" \t");
    const std::string_view index = rest.substr(0, end);
    unsigned value = 0;
    for (char c : index) value = value * 16 + static_cast<unsigned>(hex_digit(c));
    std::vector<std::uint8_t> bytes =
        end == std::string_view::npos
            ? std::vector<std::uint8_t>{}
            : parse_hex_bytes(std::string(rest.substr(end)), source, line_number);
    if (bytes.size() < 2 || bytes[1] != 3 || bytes[0] > bytes.size()) {
      where.fail("S " + std::string(index), "not a string descriptor (bLength, type 3, payload)");
    }
    bytes.resize(bytes[0] < 2 ? 2 : bytes[0]);
    init.strings.push_back({static_cast<std::uint8_t>(value), std::move(bytes)});
  }
  if (init.strings.empty()) throw InputFormatError(source, 0, "", "no string descriptors");
  return init;
}

DescriptorFile read_descriptor_file(const std::filesystem::path& path,
                                    std::optional<int> interface) {
  const std::string text = read_all(path);
  const std::string source = path.string();
  DescriptorFile file;
  file.format = detect_capture_format(text, path.extension() == ".bin");
  switch (file.format) {
    case CaptureFormat::kRawBinary:
      if (text.size() > kMaxBinaryDescriptor) {
        throw InputFormatError(source, 0, "", "too large for a report descriptor");
      }
      file.bytes.assign(text.begin(), text.end());
      break;
    case CaptureFormat::kHidRecorder: {
      std::istringstream in(text);
      file.bytes = parse_hid_recording(in, source).descriptor;
      break;
    }
    case CaptureFormat::kUsbhidDump: {
      UsbhidDump dump = parse_usbhid_dump(text, source);
      file.warnings = std::move(dump.warnings);
      std::set<int> interfaces;
      const UsbhidDumpRecord* chosen = nullptr;
      for (const UsbhidDumpRecord& r : dump.records) {
        if (!r.descriptor) continue;
        interfaces.insert(r.interface);
        if (!interface || *interface == r.interface) chosen = chosen ? chosen : &r;
      }
      if (interfaces.empty()) throw InputFormatError(source, 0, "", "no DESCRIPTOR record");
      if (!interface && interfaces.size() > 1) {
        throw InputFormatError(
            source, 0, "interface",
            "descriptors of interfaces " + interface_list(interfaces) + "; choose one");
      }
      if (chosen == nullptr) {
        throw InputFormatError(source, 0, "interface",
                               "no descriptor of interface " + std::to_string(*interface) +
                                   " (it has " + interface_list(interfaces) + ")");
      }
      file.bytes = chosen->bytes;
      file.interface = chosen->interface;
      break;
    }
    case CaptureFormat::kStringProbe:
      throw InputFormatError(source, 0, "", "string descriptors, not a report descriptor");
    case CaptureFormat::kHexText: {
      const std::vector<std::string_view> lines = lines_of(text);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        const std::string content(trim(line.substr(0, line.find('#'))));
        const auto more = parse_hex_bytes(content, source, static_cast<int>(i) + 1);
        file.bytes.insert(file.bytes.end(), more.begin(), more.end());
      }
      break;
    }
  }
  if (file.bytes.empty()) throw InputFormatError(source, 0, "", "no descriptor bytes");
  return file;
}

ReportFile read_report_file(const std::filesystem::path& path, std::optional<int> interface) {
  const std::string text = read_all(path);
  const std::string source = path.string();
  ReportFile file;
  file.format = detect_capture_format(text, false);
  switch (file.format) {
    case CaptureFormat::kHidRecorder: {
      // Reports only: the capture's descriptor is not needed (nor required) here.
      const std::vector<std::string_view> lines = lines_of(text);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!has_tag(lines[i], 'E')) continue;
        file.reports.push_back(parse_recorder_event(std::string(trim(lines[i]).substr(2)), source,
                                                    static_cast<int>(i) + 1));
      }
      break;
    }
    case CaptureFormat::kUsbhidDump: {
      UsbhidDump dump = parse_usbhid_dump(text, source);
      file.warnings = std::move(dump.warnings);
      std::set<int> interfaces;
      double first = -1.0;
      for (UsbhidDumpRecord& r : dump.records) {
        if (r.descriptor) continue;
        interfaces.insert(r.interface);
        if (interface && *interface != r.interface) continue;
        if (first < 0.0) first = r.time_s;
        file.reports.push_back({r.time_s - first, std::move(r.bytes)});
      }
      file.interfaces.assign(interfaces.begin(), interfaces.end());
      if (!interface && interfaces.size() > 1) {
        file.warnings.push_back(source + ": reports of interfaces " + interface_list(interfaces) +
                                " mixed; choose one");
      }
      break;
    }
    case CaptureFormat::kStringProbe:
    case CaptureFormat::kRawBinary:
      throw InputFormatError(
          source, 0, "",
          std::string("a ") + capture_format_name(file.format) + " file holds no input reports");
    case CaptureFormat::kHexText: {
      const std::vector<std::string_view> lines = lines_of(text);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        const std::string content(trim(line.substr(0, line.find('#'))));
        if (content.empty()) continue;
        file.reports.push_back({0.0, parse_hex_bytes(content, source, static_cast<int>(i) + 1)});
      }
      break;
    }
  }
  return file;
}

std::vector<std::uint8_t> load_descriptor_bytes(const std::filesystem::path& path) {
  return read_descriptor_file(path).bytes;
}

std::vector<RecordedReport> load_reports(const std::filesystem::path& path) {
  return read_report_file(path).reports;
}

}  // namespace impasto::input::hid
