#include <impasto/input/hid_report.hpp>

#include <algorithm>

namespace impasto::input::hid {

ReportView split_input_report(const ReportDescriptor& descriptor,
                              std::span<const std::uint8_t> report, const std::string& source) {
  if (report.empty()) throw InputFormatError(source, 0, "", "empty report");
  ReportView view;
  view.data = report;
  if (descriptor.has_report_ids) {
    view.report_id = report[0];
    view.data = report.subspan(1);
  }
  const ReportInfo* info = descriptor.find_report(ReportType::kInput, view.report_id);
  if (info == nullptr) {
    throw InputFormatError(
        source, 0, "report ID",
        "no input report " + std::to_string(view.report_id) + " in the descriptor");
  }
  const std::size_t needed = info->bytes(false);
  if (view.data.size() < needed) {
    throw InputFormatError(source, 0, "length",
                           "input report " + std::to_string(view.report_id) + " has " +
                               std::to_string(view.data.size()) +
                               " data bytes, the descriptor "
                               "declares " +
                               std::to_string(needed));
  }
  return view;
}

std::int64_t field_value(const ReportField& field, std::uint32_t index,
                         std::span<const std::uint8_t> data) {
  const std::uint32_t width = std::min<std::uint32_t>(field.bit_size, 64);
  std::uint64_t bit = static_cast<std::uint64_t>(field.bit_offset) +
                      static_cast<std::uint64_t>(index) * field.bit_size;
  std::uint64_t value = 0;
  std::uint32_t got = 0;
  while (got < width) {
    const std::uint32_t shift = static_cast<std::uint32_t>(bit % 8);
    const std::uint32_t take = std::min(8 - shift, width - got);
    const std::uint64_t byte = data[static_cast<std::size_t>(bit / 8)];
    value |= ((byte >> shift) & ((1u << take) - 1)) << got;
    got += take;
    bit += take;
  }
  if (field.is_signed() && width < 64 && (value >> (width - 1)) & 1u) {
    value |= ~std::uint64_t{0} << width;  // sign extension
  }
  return static_cast<std::int64_t>(value);
}

std::vector<UsageValue> decode_usage_values(const ReportDescriptor& descriptor,
                                            std::span<const std::uint8_t> report,
                                            const std::string& source) {
  const ReportView view = split_input_report(descriptor, report, source);
  std::vector<UsageValue> values;
  for (const ReportField& field : descriptor.fields) {
    if (field.type != ReportType::kInput || field.report_id != view.report_id) continue;
    if (field.is_constant()) continue;
    for (std::uint32_t i = 0; i < field.count; ++i) {
      const std::int64_t v = field_value(field, i, view.data);
      if (field.is_variable()) {
        values.push_back({field.usage_at(i), v});
      } else if (v >= field.logical_min && v <= field.logical_max) {
        const auto slot = static_cast<std::uint64_t>(v - field.logical_min);
        if (slot < field.usage_count()) values.push_back({field.usage_at(slot), 1});
      }
    }
  }
  return values;
}

}  // namespace impasto::input::hid
