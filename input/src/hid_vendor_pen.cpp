#include <impasto/input/hid_vendor_pen.hpp>

#include <algorithm>

namespace impasto::input::hid {

namespace {

constexpr double kMmPerInch = 25.4;

std::uint32_t le16(std::span<const std::uint8_t> b, std::size_t at) {
  return b[at] | (static_cast<std::uint32_t>(b[at + 1]) << 8);
}

std::uint32_t le24(std::span<const std::uint8_t> b, std::size_t at) {
  return le16(b, at) | (static_cast<std::uint32_t>(b[at + 2]) << 16);
}

float signed_byte(std::uint8_t b) {
  return static_cast<float>(static_cast<std::int8_t>(b));
}

// Some tablets answer any string index they do not know with their name: a payload of
// printable UTF-16 code units only is not a parameter block.
bool all_text(std::span<const std::uint8_t> d) {
  for (std::size_t i = 2; i + 1 < d.size(); i += 2) {
    if (d[i] < 0x20 || d[i] >= 0x7F || d[i + 1] != 0) return false;
  }
  return true;
}

double scaled(std::uint32_t raw, std::uint32_t max, double extent) {
  if (max == 0) return 0.0;
  return static_cast<double>(std::min(raw, max)) / static_cast<double>(max) * extent;
}

}  // namespace

const char* vendor_protocol_name(VendorProtocol protocol) {
  switch (protocol) {
    case VendorProtocol::kUcLogicV1:
      return "UC-Logic v1";
    case VendorProtocol::kUcLogicV2:
      return "UC-Logic v2";
    case VendorProtocol::kXpPen:
      return "XP-Pen";
    case VendorProtocol::kVeikkV1:
      return "Veikk v1";
    case VendorProtocol::kWacomIntuosV2:
      return "Wacom Intuos V2";
  }
  return "unknown";
}

double UcLogicParams::width_mm() const {
  return lines_per_inch == 0 ? 0.0 : max_x * kMmPerInch / lines_per_inch;
}

double UcLogicParams::height_mm() const {
  return lines_per_inch == 0 ? 0.0 : max_y * kMmPerInch / lines_per_inch;
}

namespace {

// Where a version's parameter string holds its numbers: a string descriptor (type 3) of at
// least `min_size` bytes, max x and max y at bytes `x_at` and `y_at` (16- or 24-bit, little-
// endian), max pressure (16-bit) at byte 8 and lines per inch at 10 in both.
struct UcLogicLayout {
  int version;
  std::size_t min_size, x_at, y_at;
  bool wide;  // 24-bit maxima
};

std::optional<UcLogicParams> parse_uclogic_params(std::span<const std::uint8_t> d,
                                                  const UcLogicLayout& layout) {
  if (d.size() < layout.min_size || d[1] != 3 || all_text(d)) return std::nullopt;
  const auto word = layout.wide ? le24 : le16;
  UcLogicParams p;
  p.version = layout.version;
  p.max_x = word(d, layout.x_at);
  p.max_y = word(d, layout.y_at);
  p.max_pressure = le16(d, 8);
  p.lines_per_inch = le16(d, 10);
  if (p.max_x == 0 || p.max_y == 0 || p.max_pressure == 0) return std::nullopt;
  return p;
}

}  // namespace

// String 0x64: little-endian 16-bit words after the header: max x, max y, (unknown), max
// pressure, lines per inch.
std::optional<UcLogicParams> parse_uclogic_params_v1(std::span<const std::uint8_t> d) {
  return parse_uclogic_params(d, {1, 12, 2, 4, false});
}

// String 0xC8: max x and max y 24-bit at bytes 2 and 5, max pressure 16-bit at 8, lines per
// inch at 10.
std::optional<UcLogicParams> parse_uclogic_params_v2(std::span<const std::uint8_t> d) {
  return parse_uclogic_params(d, {2, 18, 2, 5, true});
}

std::optional<UcLogicParams> uclogic_params(const InitExchange& init) {
  if (const auto* v2 = init.string(kUcLogicParamsV2)) {
    if (auto p = parse_uclogic_params_v2(*v2)) return p;
  }
  if (const auto* v1 = init.string(kUcLogicParamsV1)) return parse_uclogic_params_v1(*v1);
  return std::nullopt;
}

std::uint8_t VendorPenFormat::report_id() const {
  switch (protocol) {
    case VendorProtocol::kUcLogicV1:
      return 0x07;
    case VendorProtocol::kUcLogicV2:
      return 0x08;
    case VendorProtocol::kXpPen:
      return 0x02;
    case VendorProtocol::kVeikkV1:
      return 0x09;
    case VendorProtocol::kWacomIntuosV2:
      return 0x10;
  }
  return 0;
}

VendorPenFormat uclogic_format(const UcLogicParams& params) {
  VendorPenFormat f;
  f.protocol = params.version == 2 ? VendorProtocol::kUcLogicV2 : VendorProtocol::kUcLogicV1;
  f.max_x = params.max_x;
  f.max_y = params.max_y;
  f.max_pressure = params.max_pressure;
  f.width_mm = params.width_mm();
  f.height_mm = params.height_mm();
  f.tilt = params.version == 2;
  return f;
}

std::optional<paintcore::PenSample> decode_vendor_pen_report(const VendorPenFormat& format,
                                                             std::span<const std::uint8_t> report,
                                                             double time_s) {
  if (report.size() < 2 || report[0] != format.report_id()) return std::nullopt;
  std::span<const std::uint8_t> r = report;
  std::uint32_t x = 0, y = 0, pressure = 0;
  float tilt_x = 0.0f, tilt_y = 0.0f;
  bool in_range = true;
  std::uint8_t flags = r[1];
  switch (format.protocol) {
    case VendorProtocol::kUcLogicV1:
      // 0xE0 marks the pad's buttons sent in the pen's report.
      if (r.size() < 8 || (flags & 0xF0) == 0xE0) return std::nullopt;
      in_range = (flags & 0x40) == 0;  // set when the pen is out of range
      x = le16(r, 2);
      y = le16(r, 4);
      pressure = le16(r, 6);
      if (format.tilt && r.size() >= 10) {
        tilt_x = signed_byte(r[8]);
        tilt_y = signed_byte(r[9]);
      }
      break;
    case VendorProtocol::kUcLogicV2:
      // No in-range bit: a report means the pen is near. The high bytes of x and y follow
      // the pressure; y tilt points the other way.
      if (r.size() < 12 || (flags & 0xF0) == 0xE0) return std::nullopt;
      x = le16(r, 2) | (static_cast<std::uint32_t>(r[8]) << 16);
      y = le16(r, 4) | (static_cast<std::uint32_t>(r[9]) << 16);
      pressure = le16(r, 6);
      tilt_x = signed_byte(r[10]);
      tilt_y = -signed_byte(r[11]);
      break;
    case VendorProtocol::kXpPen:
      if (r.size() < 8 || (flags != 0xC0 && (flags & 0x10) != 0)) return std::nullopt;  // pad
      in_range = flags != 0xC0;
      x = le16(r, 2);
      y = le16(r, 4);
      pressure = le16(r, 6);
      if (r.size() >= 12) {
        x |= static_cast<std::uint32_t>(r[10]) << 16;
        y |= static_cast<std::uint32_t>(r[11]) << 16;
      }
      if (format.tilt && r.size() >= 10) {
        tilt_x = signed_byte(r[8]);
        tilt_y = signed_byte(r[9]);
      }
      break;
    case VendorProtocol::kVeikkV1:
      // 09 41 <flags> x x y y p p: the flags' high nibble is 0xA near, 0xC0 out of range.
      if (r.size() < 9 || r[1] != 0x41) return std::nullopt;
      flags = r[2];
      if (flags != 0xC0 && (flags & 0xF0) != 0xA0) return std::nullopt;
      in_range = flags != 0xC0;
      x = le16(r, 3);
      y = le16(r, 5);
      pressure = le16(r, 7);
      // Its barrel buttons are bits 1 and 2, its tip is pressure: bit 0 is not sent.
      flags = static_cast<std::uint8_t>(flags & 0x06);
      break;
    case VendorProtocol::kWacomIntuosV2:
      // 10 flags (tip 0x01, barrels 0x02 0x04, eraser 0x10, in range 0x20), x and y 24-bit,
      // pressure 16-bit, tilt x and y signed bytes.
      if (r.size() < 12) return std::nullopt;
      in_range = (flags & 0x21) != 0;  // a tip down is in range
      x = le24(r, 2);
      y = le24(r, 5);
      pressure = le16(r, 8);
      if (format.tilt) {
        tilt_x = signed_byte(r[10]);
        tilt_y = signed_byte(r[11]);
      }
      break;
  }
  paintcore::PenSample s;
  s.time_s = time_s;
  s.x_mm = scaled(x, format.max_x, format.width_mm);
  s.y_mm = scaled(y, format.max_y, format.height_mm);
  if (!in_range) return s;  // the last position, nothing pressed
  s.pressure = format.max_pressure == 0
                   ? 0.0f
                   : static_cast<float>(std::min(pressure, format.max_pressure)) /
                         static_cast<float>(format.max_pressure);
  s.tilt_x_deg = std::clamp(tilt_x, -90.0f, 90.0f);
  s.tilt_y_deg = std::clamp(tilt_y, -90.0f, 90.0f);
  std::uint32_t buttons = paintcore::kPenInRange;
  const bool tip =
      format.protocol == VendorProtocol::kVeikkV1 ? s.pressure > 0.0f : (flags & 0x01) != 0;
  if (tip) buttons |= paintcore::kPenTip;
  if (flags & 0x02) buttons |= paintcore::kPenBarrel1;
  if (flags & 0x04) buttons |= paintcore::kPenBarrel2;
  if (format.protocol == VendorProtocol::kXpPen && (flags & 0x08)) buttons |= paintcore::kPenEraser;
  if (format.protocol == VendorProtocol::kWacomIntuosV2 && (flags & 0x10)) {
    buttons |= paintcore::kPenEraser;
  }
  s.buttons = buttons;
  return s;
}

}  // namespace impasto::input::hid
