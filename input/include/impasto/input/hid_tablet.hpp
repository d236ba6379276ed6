#pragma once
// One decoder for any tablet Impasto can read: standard HID pen reports through the report
// descriptor, or a known vendor protocol chosen by vendor and product id.
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/hid_vendor.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace impasto::input::hid {

class TabletDecoder {
 public:
  // Throws UnsupportedTablet (with the reason) when neither way applies, and
  // InputFormatError when the descriptor is malformed.
  TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                std::uint16_t product_id, DecoderOptions options = {});

  // A pen sample in tablet mm, or nullopt for reports that carry no pen state. Throws
  // InputFormatError, naming `source`, for a malformed pen report.
  std::optional<paintcore::PenSample> decode(std::span<const std::uint8_t> report, double time_s,
                                             const std::string& source = "report") const;
  TabletArea area() const;
  // What `impasto hid list` shows about the pen.
  std::string describe() const;

 private:
  std::variant<PenDecoder, GraphireTablet> decoder_;
};

}  // namespace impasto::input::hid
