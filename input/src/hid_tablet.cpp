#include <impasto/input/hid_tablet.hpp>

#include <impasto/input/hid_describe.hpp>

#include <cstdio>

namespace impasto::input::hid {

namespace {

std::variant<PenDecoder, GraphireTablet> choose(std::span<const std::uint8_t> descriptor,
                                                std::uint16_t vendor_id, std::uint16_t product_id,
                                                DecoderOptions options) {
  if (const auto graphire = find_graphire_tablet(vendor_id, product_id)) return *graphire;
  return PenDecoder(parse_report_descriptor(descriptor, "device descriptor"), options);
}

}  // namespace

TabletDecoder::TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                             std::uint16_t product_id, DecoderOptions options)
    : decoder_(choose(descriptor, vendor_id, product_id, options)) {}

std::optional<paintcore::PenSample> TabletDecoder::decode(std::span<const std::uint8_t> report,
                                                          double time_s,
                                                          const std::string& source) const {
  if (const auto* pen = std::get_if<PenDecoder>(&decoder_)) {
    return pen->decode(report, time_s, source);
  }
  return decode_graphire_report(std::get<GraphireTablet>(decoder_), report, time_s);
}

TabletArea TabletDecoder::area() const {
  if (const auto* pen = std::get_if<PenDecoder>(&decoder_)) return pen->area();
  const GraphireTablet& t = std::get<GraphireTablet>(decoder_);
  return {t.max_x / t.lines_per_mm, t.max_y / t.lines_per_mm, true};
}

std::string TabletDecoder::describe() const {
  if (const auto* pen = std::get_if<PenDecoder>(&decoder_)) return describe_pen(*pen);
  const GraphireTablet& t = std::get<GraphireTablet>(decoder_);
  char text[200];
  std::snprintf(text, sizeof text,
                "%s, Wacom Graphire protocol: active area %.2f mm x %.2f mm, x 0..%d, y 0..%d, "
                "pressure %d levels; switches: tip barrel barrel2 eraser\n",
                t.name, t.max_x / t.lines_per_mm, t.max_y / t.lines_per_mm, t.max_x, t.max_y,
                t.max_pressure + 1);
  return text;
}

}  // namespace impasto::input::hid
