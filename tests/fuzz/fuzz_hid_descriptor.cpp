// Fuzz target: any bytes as a report descriptor, then as reports for it. Nothing may crash;
// malformed input may only throw the project's documented errors.
#include <impasto/input/hid_describe.hpp>
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/hid_report.hpp>
#include <impasto/input/hid_vendor.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace hid = impasto::input::hid;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The first byte says how much of the rest is descriptor (in 8-byte steps, capped by the
  // input); what follows is reports, each prefixed with its length. Seeds that are plain
  // descriptors still parse: their first byte is then a length.
  if (size == 0) return 0;
  const std::span<const std::uint8_t> input(data + 1, size - 1);
  const std::size_t descriptor_size = std::min<std::size_t>(input.size(), data[0] * 8u);
  const auto descriptor = input.first(descriptor_size);
  auto rest = input.subspan(descriptor_size);

  // Whole input as a descriptor too, so every byte is also seen as an item.
  try {
    (void)hid::parse_report_descriptor(std::span(data, size), "fuzz");
  } catch (const impasto::input::InputFormatError&) {
  }

  std::optional<hid::ReportDescriptor> parsed;
  try {
    parsed = hid::parse_report_descriptor(descriptor, "fuzz");
  } catch (const impasto::input::InputFormatError&) {
    return 0;
  }
  (void)hid::describe_reports(*parsed);
  std::optional<hid::PenDecoder> pen;
  try {
    pen.emplace(*parsed);
    (void)hid::describe_pen(*pen);
  } catch (const hid::UnsupportedTablet&) {
  }
  const hid::GraphireTablet graphire = *hid::find_graphire_tablet(0x056A, 0x0061);
  while (!rest.empty()) {
    const std::size_t length = std::min<std::size_t>(rest[0], rest.size() - 1);
    const auto report = rest.subspan(1, length);
    rest = rest.subspan(1 + length);
    try {
      for (const hid::UsageValue& v : hid::decode_usage_values(*parsed, report, "fuzz")) {
        (void)hid::usage_name(v.usage);
      }
    } catch (const impasto::input::InputFormatError&) {
    }
    if (pen) {
      try {
        (void)pen->decode(report, 0.0);
      } catch (const impasto::input::InputFormatError&) {
      }
    }
    (void)hid::decode_graphire_report(graphire, report, 0.0);
  }
  return 0;
}
