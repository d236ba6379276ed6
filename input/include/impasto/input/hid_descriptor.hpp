#pragma once
// A HID report descriptor (USB HID 1.11, section 6.2.2) parsed into the fields of each
// report: where each field's bits are, what usages they carry, their logical and physical
// extents and unit. Any byte string is accepted as input: malformed descriptors give an
// InputFormatError naming the byte offset, never undefined behaviour.
#include <impasto/input/hid_usage.hpp>
#include <impasto/input/stroke_error.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace impasto::input::hid {

enum class ReportType : std::uint8_t { kInput, kOutput, kFeature };
const char* report_type_name(ReportType type);

// The kinds of collection (HID 1.11, 6.2.2.6); values above 6 are reserved or vendor.
enum class CollectionType : std::uint8_t {
  kPhysical = 0,
  kApplication = 1,
  kLogical = 2,
  kReport = 3,
  kNamedArray = 4,
  kUsageSwitch = 5,
  kUsageModifier = 6,
};

struct Collection {
  Usage usage = 0;
  std::uint8_t type = 0;  // a CollectionType, or a reserved/vendor value
  int parent = -1;        // index into ReportDescriptor::collections, -1 at the top
};

// A HID unit (6.2.2.7): the system nibble and the exponents of length, mass, time, ...
// plus the base-10 exponent of the value.
struct Unit {
  std::uint32_t code = 0;
  int exponent = 0;

  int system() const { return static_cast<int>(code & 0xF); }
  // The exponent of nibble n (1 length/angle, 2 mass, 3 time, ...), -8..7.
  int nibble_exponent(int n) const;
  // Millimetres per physical unit for a pure length (cm or inch to the first power).
  std::optional<double> millimetres() const;
  // Degrees per physical unit for a pure angle (radian or degree to the first power).
  std::optional<double> degrees() const;
  // "cm", "inch", "deg", "rad" with exponents, or "none".
  std::string name() const;
  bool operator==(const Unit&) const = default;
};

// A run of usages first..last (a single usage has first == last).
struct UsageRange {
  Usage first = 0;
  Usage last = 0;
  bool operator==(const UsageRange&) const = default;
};

// One main item (Input, Output or Feature): `count` elements of `bit_size` bits each.
struct ReportField {
  ReportType type = ReportType::kInput;
  std::uint8_t report_id = 0;    // 0 when the descriptor has no report IDs
  std::uint32_t bit_offset = 0;  // of the first element, counted after the report ID byte
  std::uint32_t bit_size = 0;    // of each element
  std::uint32_t count = 0;
  std::uint32_t flags = 0;  // the main item's data bits (constant, variable, relative, ...)
  std::vector<UsageRange> usages;
  std::int64_t logical_min = 0;
  std::int64_t logical_max = 0;
  std::int64_t physical_min = 0;  // equal to the logical extents when the descriptor gives none
  std::int64_t physical_max = 0;
  Unit unit;
  int collection = -1;  // the innermost collection holding the field

  bool is_constant() const { return (flags & 0x01) != 0; }
  bool is_variable() const { return (flags & 0x02) != 0; }
  bool is_relative() const { return (flags & 0x04) != 0; }
  bool has_null_state() const { return (flags & 0x40) != 0; }
  bool is_signed() const { return logical_min < 0; }

  // The number of usages listed (ranges counted in full).
  std::uint64_t usage_count() const;
  // The usage of usage slot i: the last usage repeats past the end of the list (6.2.2.8).
  // 0 when the field has no usages.
  Usage usage_at(std::uint64_t i) const;
};

// The total size of one report.
struct ReportInfo {
  ReportType type = ReportType::kInput;
  std::uint8_t report_id = 0;
  std::uint32_t bits = 0;  // without the report ID byte

  // Bytes on the wire, the report ID byte included when there is one.
  std::size_t bytes(bool has_report_ids) const { return (bits + 7) / 8 + (has_report_ids ? 1 : 0); }
};

struct ReportDescriptor {
  std::vector<Collection> collections;
  std::vector<ReportField> fields;
  std::vector<ReportInfo> reports;  // in order of first appearance
  bool has_report_ids = false;

  const ReportInfo* find_report(ReportType type, std::uint8_t report_id) const;
  // The usage of the top-level (application) collection that holds a field, 0 if none.
  Usage application_of(const ReportField& field) const;
};

// Parses a descriptor. `source` names it in error messages ("file.bin").
ReportDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes,
                                         const std::string& source = "report descriptor");

}  // namespace impasto::input::hid
