#pragma once
// What a vendor handshake exchanges with a tablet before it reports at full resolution:
// string descriptors read, feature reports read, output reports sent.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::input::hid {

// String descriptors read from a device, raw (bLength, type 3, then the payload), by index.
struct StringDescriptor {
  std::uint8_t index = 0;
  std::vector<std::uint8_t> bytes;
  bool operator==(const StringDescriptor&) const = default;
};
// The payload of a string descriptor as text (UTF-16LE, non-ASCII as '?').
std::string string_descriptor_text(const std::vector<std::uint8_t>& bytes);

// What a handshake read from (or sent to) a tablet: its string descriptors, feature reports
// read and output reports sent, in order. Stored in captures so they replay.
struct InitExchange {
  std::vector<StringDescriptor> strings;
  std::vector<std::vector<std::uint8_t>> feature_reports;
  std::vector<std::vector<std::uint8_t>> output_reports;
  std::string manufacturer;              // the probe's "M" line, when given
  std::string product;                   // its "P" line
  std::vector<std::uint8_t> unanswered;  // indices the device did not answer

  const std::vector<std::uint8_t>* string(std::uint8_t index) const;
  bool empty() const {
    return strings.empty() && feature_reports.empty() && output_reports.empty();
  }
  bool operator==(const InitExchange&) const = default;
};

// A DIGImend probe file: "S 64 0E 03 40 9C ..." (index in hex, the descriptor's bytes),
// "M ..." / "P ..." (manufacturer and product strings, UTF-16LE bytes) and "Failed to get
// string descriptor 0xC8: ..." lines.
InitExchange parse_string_probe(std::string_view text, const std::string& source);

}  // namespace impasto::input::hid
