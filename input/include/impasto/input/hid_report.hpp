#pragma once
// Reading the values of a report's fields, as a report descriptor lays them out.
#include <impasto/input/hid_descriptor.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace impasto::input::hid {

// A report split into its ID and its data (the bytes after the ID byte).
struct ReportView {
  std::uint8_t report_id = 0;
  std::span<const std::uint8_t> data;
};

// Splits a raw input report. Throws InputFormatError (naming `source`) when the report is
// empty, its ID is not an input report of the descriptor, or it is shorter than declared.
// Longer reports are accepted; the extra bytes are ignored.
ReportView split_input_report(const ReportDescriptor& descriptor,
                              std::span<const std::uint8_t> report,
                              const std::string& source = "report");

// Element `index` of a field, sign-extended when the field's logical minimum is negative.
// Fields wider than 64 bits give their low 64 bits. The data must hold the field's bits
// (split_input_report checks that).
std::int64_t field_value(const ReportField& field, std::uint32_t index,
                         std::span<const std::uint8_t> data);

struct UsageValue {
  Usage usage = 0;
  std::int64_t value = 0;
  bool operator==(const UsageValue&) const = default;
};

// Every usage value of an input report, in field order, constant fields skipped: a variable
// field gives one value per element; an array field gives, for each element whose value
// lies in the logical range, the usage that value selects, with value 1.
std::vector<UsageValue> decode_usage_values(const ReportDescriptor& descriptor,
                                            std::span<const std::uint8_t> report,
                                            const std::string& source = "report");

}  // namespace impasto::input::hid
