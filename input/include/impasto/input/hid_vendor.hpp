#pragma once
// Tablets whose pen speaks a vendor protocol inside vendor-defined HID reports. Only
// protocols checked against a real recording are listed.
#include <impasto/paintcore/pen_sample.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace impasto::input::hid {

// Wacom's "Graphire" pen report (report ID 2) as the Linux wacom driver reads it:
// byte 1 status (0x80 in proximity, bits 5-6 tool: 0 pen, 1 eraser; 0x01 tip, 0x02 and
// 0x04 side buttons), x and y little-endian 16-bit at bytes 2 and 4, pressure in byte 6
// plus the low two bits of byte 7.
struct GraphireTablet {
  const char* name;
  std::uint16_t product_id;
  int max_x;
  int max_y;
  int max_pressure;
  double lines_per_mm;
};

// The Graphire-protocol tablet with this Wacom product id, if Impasto knows it.
std::optional<GraphireTablet> find_graphire_tablet(std::uint16_t vendor_id,
                                                   std::uint16_t product_id);

// Decodes one Graphire report (report ID included); nullopt for other reports or short ones.
std::optional<paintcore::PenSample> decode_graphire_report(const GraphireTablet& tablet,
                                                           std::span<const std::uint8_t> report,
                                                           double time_s);

}  // namespace impasto::input::hid
