#include <impasto/input/hid_vendor.hpp>

#include <algorithm>

namespace impasto::input::hid {

namespace {

constexpr std::uint16_t kWacom = 0x056A;

// Extents and resolution as the Linux wacom driver lists them (wacom_features_0x61).
constexpr GraphireTablet kGraphireTablets[] = {
    {"Wacom PenStation2 / PenPartner", 0x0061, 3250, 2320, 255, 50.0},
};

}  // namespace

std::optional<GraphireTablet> find_graphire_tablet(std::uint16_t vendor_id,
                                                   std::uint16_t product_id) {
  if (vendor_id != kWacom) return std::nullopt;
  for (const GraphireTablet& t : kGraphireTablets) {
    if (t.product_id == product_id) return t;
  }
  return std::nullopt;
}

std::optional<paintcore::PenSample> decode_graphire_report(const GraphireTablet& tablet,
                                                           std::span<const std::uint8_t> report,
                                                           double time_s) {
  constexpr std::uint8_t kPenReport = 2;
  if (report.size() < 8 || report[0] != kPenReport) return std::nullopt;
  const std::uint8_t status = report[1];
  const int tool = (status >> 5) & 0x3;
  if (tool >= 2) return std::nullopt;  // a mouse, not a pen
  const bool in_range = (status & 0x80) != 0;
  const int x = report[2] | (report[3] << 8);
  const int y = report[4] | (report[5] << 8);
  const int pressure = report[6] | ((report[7] & 0x03) << 8);

  paintcore::PenSample s;
  s.time_s = time_s;
  s.x_mm = std::clamp(x, 0, tablet.max_x) / tablet.lines_per_mm;
  s.y_mm = std::clamp(y, 0, tablet.max_y) / tablet.lines_per_mm;
  if (in_range) {
    s.pressure = static_cast<float>(std::clamp(pressure, 0, tablet.max_pressure)) /
                 static_cast<float>(tablet.max_pressure);
    s.buttons |= paintcore::kPenInRange;
    if (status & 0x01) s.buttons |= paintcore::kPenTip;
    if (status & 0x02) s.buttons |= paintcore::kPenBarrel1;
    if (status & 0x04) s.buttons |= paintcore::kPenBarrel2;
    if (tool == 1) s.buttons |= paintcore::kPenEraser;
  }
  return s;
}

}  // namespace impasto::input::hid
