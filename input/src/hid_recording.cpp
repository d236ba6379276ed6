#include <impasto/input/hid_recording.hpp>

#include <impasto/input/hid_tablet.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"
#include "recording_input.hpp"
#include "text_fields.hpp"

namespace impasto::input::hid {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string trim(const std::string& text) {
  return std::string(util::trim(text));
}

// The byte count and bytes after a tag: "R: 3 05 0d 09" or "E: 0.5 3 02 00 01".
std::vector<std::uint8_t> counted_bytes(const std::string& rest, const std::string& source,
                                        int line, const char* field) {
  std::istringstream words(rest);
  std::string count_text;
  words >> count_text;
  const detail::LineContext where{source, line};
  const std::int64_t count = detail::parse_integer(count_text, where, field);
  std::string bytes_text((std::istreambuf_iterator<char>(words)), std::istreambuf_iterator<char>());
  std::vector<std::uint8_t> bytes = parse_hex_bytes(bytes_text, source, line);
  if (count < 0 || static_cast<std::uint64_t>(count) != bytes.size()) {
    where.fail(field, "declares " + std::to_string(count) + " bytes but lists " +
                          std::to_string(bytes.size()));
  }
  return bytes;
}

}  // namespace

std::vector<std::uint8_t> parse_hex_bytes(const std::string& text, const std::string& source,
                                          int line) {
  std::vector<std::uint8_t> bytes;
  std::size_t i = 0;
  const detail::LineContext where{source, line};
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\n') {
      ++i;
      continue;
    }
    std::size_t start = i;
    if (c == '0' && i + 1 < text.size() && (text[i + 1] == 'x' || text[i + 1] == 'X')) start += 2;
    std::size_t end = start;
    while (end < text.size() && hex_digit(text[end]) >= 0) ++end;
    const bool separated = end == text.size() || text[end] == ' ' || text[end] == '\t' ||
                           text[end] == ',' || text[end] == '\r' || text[end] == '\n';
    if (end - start != 2 || !separated) {
      std::size_t stop = start;
      while (stop < text.size() && text[stop] != ' ' && text[stop] != ',') ++stop;
      where.fail("byte " + std::to_string(bytes.size() + 1),
                 "expected two hex digits, found " +
                     files::excerpt(std::string_view(text).substr(i, stop - i), 20));
    }
    bytes.push_back(
        static_cast<std::uint8_t>(hex_digit(text[start]) * 16 + hex_digit(text[start + 1])));
    i = end;
  }
  return bytes;
}

// The part of an "E:" line after the tag: "seconds count bytes...".
RecordedReport parse_recorder_event(const std::string& rest, const std::string& source, int line) {
  std::istringstream words(rest);
  std::string time_text;
  words >> time_text;
  RecordedReport report;
  report.time_s = detail::parse_double(time_text, {source, line}, "time");
  std::string bytes_text((std::istreambuf_iterator<char>(words)), std::istreambuf_iterator<char>());
  report.bytes = counted_bytes(bytes_text, source, line, "E");
  return report;
}

HidRecording parse_hid_recording(std::istream& in, const std::string& source) {
  HidRecording recording;
  std::string line;
  int line_number = 0;
  bool has_descriptor = false;
  while (std::getline(in, line)) {
    ++line_number;
    const detail::LineContext where{source, line_number};
    const std::string text = trim(line);
    if (text.empty() || text[0] == '#') continue;
    if (text.size() < 2 || text[1] != ':') where.fail("", "expected a 'X: ...' record");
    const std::string rest = text.substr(2);
    switch (text[0]) {
      case 'R':
        if (has_descriptor) where.fail("R", "a second descriptor; one device per file");
        recording.descriptor = counted_bytes(rest, source, line_number, "R");
        has_descriptor = true;
        break;
      case 'N':
        recording.name = trim(rest);
        break;
      case 'P':
        recording.phys = trim(rest);
        break;
      case 'I': {
        std::istringstream words(rest);
        std::string bus, vendor, product, extra;
        if (!(words >> bus >> vendor >> product) || (words >> extra)) {
          where.fail("I", "expected 'I: bus vendor product' in hex");
        }
        const auto hex = [&](const std::string& word, std::uint32_t max) {
          std::uint32_t value = 0;
          for (char c : word) {
            const int d = hex_digit(c);
            if (d < 0 || value > (max >> 4))
              where.fail("I", "bad hex number " + files::excerpt(word));
            value = value * 16 + static_cast<std::uint32_t>(d);
          }
          return value;
        };
        recording.bus = hex(bus, 0xFFFF);
        recording.vendor_id = static_cast<std::uint16_t>(hex(vendor, 0xFFFF));
        recording.product_id = static_cast<std::uint16_t>(hex(product, 0xFFFF));
        break;
      }
      case 'E':
        recording.reports.push_back(parse_recorder_event(rest, source, line_number));
        break;
      case 'S': {
        std::istringstream words(rest);
        std::string index_text;
        words >> index_text;
        std::uint32_t index = 0;
        for (char c : index_text) {
          const int d = hex_digit(c);
          if (d < 0 || index > 0xF)
            where.fail("S", "bad string index " + files::excerpt(index_text));
          index = index * 16 + static_cast<std::uint32_t>(d);
        }
        if (index_text.empty()) where.fail("S", "expected 'S: index count bytes'");
        std::string bytes_text((std::istreambuf_iterator<char>(words)),
                               std::istreambuf_iterator<char>());
        recording.init.strings.push_back({static_cast<std::uint8_t>(index),
                                          counted_bytes(bytes_text, source, line_number, "S")});
        break;
      }
      case 'F':
        recording.init.feature_reports.push_back(counted_bytes(rest, source, line_number, "F"));
        break;
      case 'O':
        recording.init.output_reports.push_back(counted_bytes(rest, source, line_number, "O"));
        break;
      default:
        break;  // D:, and tags of later hid-recorder versions, carry nothing we need
    }
  }
  if (!has_descriptor) throw InputFormatError(source, 0, "R", "no descriptor ('R:' line)");
  return recording;
}

HidRecording read_hid_recording(const std::filesystem::path& path) {
  const auto in = detail::open_recording(path, "HID recording");
  return parse_hid_recording(in->stream(), path.string());
}

std::string recorder_event_line(const RecordedReport& report) {
  char head[64];
  std::snprintf(head, sizeof head, "E: %.6f %zu", report.time_s, report.bytes.size());
  std::string line = head;
  for (std::uint8_t b : report.bytes) {
    char hex[4];
    std::snprintf(hex, sizeof hex, " %02x", b);
    line += hex;
  }
  return line;
}

void write_hid_recording(std::ostream& out, const HidRecording& recording) {
  out << "D: 0\nR: " << recording.descriptor.size();
  for (std::uint8_t b : recording.descriptor) {
    char hex[4];
    std::snprintf(hex, sizeof hex, " %02x", b);
    out << hex;
  }
  out << "\nN: " << recording.name << "\nP: " << recording.phys << "\n";
  char id[48];
  std::snprintf(id, sizeof id, "I: %x %04x %04x\n", recording.bus, recording.vendor_id,
                recording.product_id);
  out << id;
  const auto bytes_line = [&](const char* tag, const std::vector<std::uint8_t>& bytes) {
    out << tag << bytes.size();
    for (std::uint8_t b : bytes) {
      char hex[4];
      std::snprintf(hex, sizeof hex, " %02x", b);
      out << hex;
    }
    out << "\n";
  };
  for (const StringDescriptor& s : recording.init.strings) {
    char tag[16];
    std::snprintf(tag, sizeof tag, "S: %02x ", s.index);
    bytes_line(tag, s.bytes);
  }
  for (const auto& f : recording.init.feature_reports) bytes_line("F: ", f);
  for (const auto& o : recording.init.output_reports) bytes_line("O: ", o);
  out << "D: 0\n";
  for (const RecordedReport& report : recording.reports) out << recorder_event_line(report) << "\n";
}

std::vector<paintcore::PenSample> decode_recording(const HidRecording& recording) {
  const TabletDecoder decoder(recording.descriptor, recording.vendor_id, recording.product_id,
                              recording.init, default_tablet_models());
  std::vector<paintcore::PenSample> samples;
  for (const RecordedReport& r : recording.reports) {
    if (auto s = decoder.decode(r.bytes, r.time_s)) samples.push_back(*s);
  }
  return samples;
}

std::vector<paintcore::PenSample> decode_recording(const std::filesystem::path& path) {
  return decode_recording(read_hid_recording(path));
}

}  // namespace impasto::input::hid
