#include <impasto/input/hid_descriptor.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace impasto::input::hid {

namespace {

// Limits that keep a hostile descriptor from asking for absurd amounts of memory. Linux
// allows descriptors of 4 KiB and reports of 16 KiB; these are generous beyond that.
constexpr std::uint64_t kMaxReportBits = 16384 * 8;
constexpr std::uint32_t kMaxFieldBits = 256;
constexpr std::size_t kMaxPushDepth = 64;
constexpr std::size_t kMaxCollectionDepth = 64;

enum class ItemType : std::uint8_t { kMain = 0, kGlobal = 1, kLocal = 2, kReserved = 3 };

// An extent item's data as written, read signed or not once its field is known.
struct RawValue {
  std::uint32_t raw = 0;
  int size = 0;  // bytes
};

// The state the Global items set, saved and restored by Push and Pop.
struct GlobalState {
  std::uint16_t usage_page = 0;
  RawValue logical_min, logical_max, physical_min, physical_max;
  int unit_exponent = 0;
  std::uint32_t unit = 0;
  std::uint32_t report_size = 0;
  std::uint8_t report_id = 0;
  std::uint32_t report_count = 0;
};

// The state the Local items set; cleared after every Main item.
struct LocalState {
  std::vector<UsageRange> usages;
  std::optional<Usage> usage_min;
  std::optional<Usage> usage_max;
};

std::int64_t as_signed(std::uint32_t raw, int size) {
  switch (size) {
    case 1:
      return static_cast<std::int8_t>(raw & 0xFF);
    case 2:
      return static_cast<std::int16_t>(raw & 0xFFFF);
    case 4:
      return static_cast<std::int32_t>(raw);
    default:
      return 0;
  }
}

// A maximum is read as signed only when its minimum is negative; devices commonly write
// 255 as the one byte 0xFF (as Linux's hid-core does).
std::int64_t extent_max(std::int64_t min, std::uint32_t raw, int size) {
  return min < 0 ? as_signed(raw, size) : static_cast<std::int64_t>(raw);
}

// Items with 4 bytes of data for Usage, Usage Minimum and Usage Maximum carry their page.
Usage full_usage(std::uint32_t data, int size, std::uint16_t page) {
  return size == 4 ? data : make_usage(page, static_cast<std::uint16_t>(data));
}

class Parser {
 public:
  Parser(std::span<const std::uint8_t> bytes, const std::string& source)
      : bytes_(bytes), source_(source) {}

  ReportDescriptor parse() {
    std::size_t pos = 0;
    while (pos < bytes_.size()) {
      item_offset_ = pos;
      const std::uint8_t prefix = bytes_[pos];
      if (prefix == 0xFE) {  // long item: size, tag, data; no long items are defined
        if (bytes_.size() - pos < 3) fail("truncated long item");
        const std::size_t size = bytes_[pos + 1];
        if (bytes_.size() - pos - 3 < size) fail("truncated long item");
        pos += 3 + size;
        continue;
      }
      const int size = (prefix & 0x3) == 3 ? 4 : (prefix & 0x3);
      const auto type = static_cast<ItemType>((prefix >> 2) & 0x3);
      const int tag = prefix >> 4;
      if (bytes_.size() - pos - 1 < static_cast<std::size_t>(size)) {
        fail("truncated item (needs " + std::to_string(size) + " data bytes)");
      }
      std::uint32_t data = 0;
      for (int i = 0; i < size; ++i)
        data |= static_cast<std::uint32_t>(bytes_[pos + 1 + i]) << (8 * i);
      pos += 1 + static_cast<std::size_t>(size);
      switch (type) {
        case ItemType::kMain:
          main_item(tag, data);
          break;
        case ItemType::kGlobal:
          global_item(tag, data, size);
          break;
        case ItemType::kLocal:
          local_item(tag, data, size);
          break;
        case ItemType::kReserved:
          fail("reserved item type");
      }
    }
    item_offset_ = bytes_.size();
    if (!open_.empty()) fail(std::to_string(open_.size()) + " collection(s) not closed");
    return std::move(result_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputFormatError(source_, 0, "byte " + std::to_string(item_offset_), problem);
  }

  void main_item(int tag, std::uint32_t data) {
    switch (tag) {
      case 0x8:
        add_field(ReportType::kInput, data);
        break;
      case 0x9:
        add_field(ReportType::kOutput, data);
        break;
      case 0xB:
        add_field(ReportType::kFeature, data);
        break;
      case 0xA:
        open_collection(data);
        break;
      case 0xC:
        if (open_.empty()) fail("End Collection without an open collection");
        open_.pop_back();
        break;
      default:
        fail("unknown main item tag " + std::to_string(tag));
    }
    local_ = LocalState{};
  }

  void open_collection(std::uint32_t data) {
    if (open_.size() >= kMaxCollectionDepth) fail("collections nested too deeply");
    Collection c;
    finish_usage_range();
    c.usage = local_.usages.empty() ? 0 : local_.usages.front().first;
    c.type = static_cast<std::uint8_t>(data & 0xFF);
    c.parent = open_.empty() ? -1 : open_.back();
    result_.collections.push_back(c);
    open_.push_back(static_cast<int>(result_.collections.size() - 1));
  }

  void add_field(ReportType type, std::uint32_t flags) {
    finish_usage_range();
    const GlobalState& g = global_;
    if (g.report_size > kMaxFieldBits) {
      fail("report size " + std::to_string(g.report_size) + " bits is over " +
           std::to_string(kMaxFieldBits));
    }
    ReportInfo& report = report_info(type, g.report_id);
    const std::uint64_t bits = static_cast<std::uint64_t>(g.report_size) * g.report_count;
    if (report.bits + bits > kMaxReportBits) {
      fail("report " + std::to_string(g.report_id) + " is larger than " +
           std::to_string(kMaxReportBits / 8) + " bytes");
    }
    ReportField field;
    field.type = type;
    field.report_id = g.report_id;
    field.bit_offset = report.bits;
    field.bit_size = g.report_size;
    field.count = g.report_count;
    field.flags = flags;
    field.usages = std::move(local_.usages);
    field.logical_min = as_signed(g.logical_min.raw, g.logical_min.size);
    field.logical_max = extent_max(field.logical_min, g.logical_max.raw, g.logical_max.size);
    field.physical_min = as_signed(g.physical_min.raw, g.physical_min.size);
    field.physical_max = extent_max(field.physical_min, g.physical_max.raw, g.physical_max.size);
    if (field.physical_min == 0 && field.physical_max == 0) {  // none given: as logical
      field.physical_min = field.logical_min;
      field.physical_max = field.logical_max;
    }
    field.unit = Unit{g.unit, g.unit_exponent};
    field.collection = open_.empty() ? -1 : open_.back();
    report.bits += static_cast<std::uint32_t>(bits);
    if (bits > 0) result_.fields.push_back(std::move(field));
  }

  ReportInfo& report_info(ReportType type, std::uint8_t id) {
    for (ReportInfo& r : result_.reports) {
      if (r.type == type && r.report_id == id) return r;
    }
    result_.reports.push_back({type, id, 0});
    return result_.reports.back();
  }

  void global_item(int tag, std::uint32_t data, int size) {
    GlobalState& g = global_;
    switch (tag) {
      case 0x0:
        g.usage_page = static_cast<std::uint16_t>(data);
        break;
      case 0x1:
        g.logical_min = {data, size};
        break;
      case 0x2:
        g.logical_max = {data, size};
        break;
      case 0x3:
        g.physical_min = {data, size};
        break;
      case 0x4:
        g.physical_max = {data, size};
        break;
      case 0x5:
        // Normally a 4-bit two's complement nibble; some devices write a signed byte.
        g.unit_exponent = (size == 1 && data <= 0xF)
                              ? (data >= 8 ? static_cast<int>(data) - 16 : static_cast<int>(data))
                              : static_cast<int>(as_signed(data, size));
        if (g.unit_exponent < -32 || g.unit_exponent > 32) fail("unit exponent out of range");
        break;
      case 0x6:
        g.unit = data;
        break;
      case 0x7:
        g.report_size = data;
        break;
      case 0x8:
        if (data == 0 || data > 0xFF) fail("report ID must be 1..255");
        g.report_id = static_cast<std::uint8_t>(data);
        result_.has_report_ids = true;
        break;
      case 0x9:
        g.report_count = data;
        break;
      case 0xA:
        if (stack_.size() >= kMaxPushDepth) fail("Push nested too deeply");
        stack_.push_back(g);
        break;
      case 0xB:
        if (stack_.empty()) fail("Pop without Push");
        g = stack_.back();
        stack_.pop_back();
        break;
      default:
        fail("unknown global item tag " + std::to_string(tag));
    }
  }

  void local_item(int tag, std::uint32_t data, int size) {
    switch (tag) {
      case 0x0: {
        const Usage u = full_usage(data, size, global_.usage_page);
        local_.usages.push_back({u, u});
        break;
      }
      case 0x1:
        local_.usage_min = full_usage(data, size, global_.usage_page);
        finish_usage_range();
        break;
      case 0x2:
        local_.usage_max = full_usage(data, size, global_.usage_page);
        finish_usage_range();
        break;
      default:
        break;  // designators, strings and delimiters do not change the report layout
    }
  }

  // A Usage Minimum and Usage Maximum pair (in either order) makes one range.
  void finish_usage_range() {
    if (!local_.usage_min || !local_.usage_max) return;
    const Usage first = *local_.usage_min;
    const Usage last = *local_.usage_max;
    if (first > last) fail("Usage Minimum is greater than Usage Maximum");
    local_.usages.push_back({first, last});
    local_.usage_min.reset();
    local_.usage_max.reset();
  }

  std::span<const std::uint8_t> bytes_;
  const std::string& source_;
  std::size_t item_offset_ = 0;
  GlobalState global_;
  std::vector<GlobalState> stack_;
  LocalState local_;
  std::vector<int> open_;  // indices of the open collections, innermost last
  ReportDescriptor result_;
};

}  // namespace

const char* report_type_name(ReportType type) {
  switch (type) {
    case ReportType::kInput:
      return "Input";
    case ReportType::kOutput:
      return "Output";
    case ReportType::kFeature:
      return "Feature";
  }
  return "?";
}

int Unit::nibble_exponent(int n) const {
  const int nibble = static_cast<int>((code >> (4 * n)) & 0xF);
  return nibble >= 8 ? nibble - 16 : nibble;
}

namespace {

// True when only nibble 1 (length or angle) is set, to the first power.
bool first_power_of_nibble_one(const Unit& unit) {
  if (unit.nibble_exponent(1) != 1) return false;
  for (int n = 2; n < 8; ++n) {
    if (unit.nibble_exponent(n) != 0) return false;
  }
  return true;
}

}  // namespace

std::optional<double> Unit::millimetres() const {
  if (!first_power_of_nibble_one(*this)) return std::nullopt;
  const double scale = std::pow(10.0, exponent);
  if (system() == 1) return 10.0 * scale;  // SI linear: centimetre
  if (system() == 3) return 25.4 * scale;  // English linear: inch
  return std::nullopt;
}

std::optional<double> Unit::degrees() const {
  if (!first_power_of_nibble_one(*this)) return std::nullopt;
  const double scale = std::pow(10.0, exponent);
  if (system() == 2) return 180.0 / std::numbers::pi * scale;  // SI rotation: radian
  if (system() == 4) return scale;                             // English rotation: degree
  return std::nullopt;
}

std::string Unit::name() const {
  if (code == 0) return "none";
  static const char* const kLength[] = {"", "cm", "rad", "inch", "deg"};
  std::string text;
  if (system() >= 1 && system() <= 4 && code <= 0xFF) {
    text = kLength[system()];
    if (nibble_exponent(1) != 1) {
      text += '^';  // appended piecewise: GCC 12 -O3 warns falsely on "..." + std::string
      text += std::to_string(nibble_exponent(1));
    }
  } else {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%X", static_cast<unsigned>(code));
    text = std::string("unit ") + hex;
  }
  if (exponent != 0) {
    text += " x10^";
    text += std::to_string(exponent);
  }
  return text;
}

std::uint64_t ReportField::usage_count() const {
  std::uint64_t n = 0;
  for (const UsageRange& r : usages) n += static_cast<std::uint64_t>(r.last - r.first) + 1;
  return n;
}

Usage ReportField::usage_at(std::uint64_t i) const {
  if (usages.empty()) return 0;
  for (const UsageRange& r : usages) {
    const std::uint64_t length = static_cast<std::uint64_t>(r.last - r.first) + 1;
    if (i < length) return r.first + static_cast<Usage>(i);
    i -= length;
  }
  return usages.back().last;
}

const ReportInfo* ReportDescriptor::find_report(ReportType type, std::uint8_t report_id) const {
  for (const ReportInfo& r : reports) {
    if (r.type == type && r.report_id == report_id) return &r;
  }
  return nullptr;
}

Usage ReportDescriptor::application_of(const ReportField& field) const {
  Usage application = 0;
  for (int c = field.collection; c >= 0 && c < static_cast<int>(collections.size());
       c = collections[static_cast<std::size_t>(c)].parent) {
    if (collections[static_cast<std::size_t>(c)].type ==
        static_cast<std::uint8_t>(CollectionType::kApplication)) {
      application = collections[static_cast<std::size_t>(c)].usage;
    }
  }
  return application;
}

ReportDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes,
                                         const std::string& source) {
  return Parser(bytes, source).parse();
}

}  // namespace impasto::input::hid
