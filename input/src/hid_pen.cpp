#include <impasto/input/hid_pen.hpp>

#include <impasto/input/hid_report.hpp>

#include <algorithm>
#include <cmath>

namespace impasto::input::hid {

namespace {

using paintcore::PenSample;

using UsageMap = Usage (*)(Usage);

Usage same_usage(Usage u) {
  return u;
}

// True when the field lies in a collection that makes it part of a pen: a Stylus collection,
// or a Digitizer/Pen application collection.
bool in_pen_collection(const ReportDescriptor& d, const ReportField& field, UsageMap map) {
  for (int c = field.collection; c >= 0; c = d.collections[static_cast<std::size_t>(c)].parent) {
    const Collection& collection = d.collections[static_cast<std::size_t>(c)];
    const Usage u = map(collection.usage);
    if (u == usage::kStylus) return true;
    if (collection.type == static_cast<std::uint8_t>(CollectionType::kApplication) &&
        (u == usage::kPen || u == usage::kDigitizer)) {
      return true;
    }
  }
  return false;
}

// Touch contacts carry X, Y and a Tip Switch too: never a pen.
bool in_touch_collection(const ReportDescriptor& d, const ReportField& field) {
  constexpr Usage kTouchScreen = make_usage(page::kDigitizer, 0x04);
  constexpr Usage kTouchPad = make_usage(page::kDigitizer, 0x05);
  constexpr Usage kFinger = make_usage(page::kDigitizer, 0x22);
  for (int c = field.collection; c >= 0; c = d.collections[static_cast<std::size_t>(c)].parent) {
    const Usage u = d.collections[static_cast<std::size_t>(c)].usage;
    if (u == kTouchScreen || u == kTouchPad || u == kFinger) return true;
  }
  return false;
}

PenAxis axis_of(const ReportField& field, int index, std::uint32_t element) {
  return {index,
          element,
          field.logical_min,
          field.logical_max,
          field.physical_min,
          field.physical_max,
          field.unit};
}

// Fills the slot of `usage` in the layout, if the layout has one for it. The first field
// carrying a usage wins.
void assign(PenReportLayout& layout, Usage u, const PenAxis& axis) {
  PenAxis* slot = nullptr;
  switch (u) {
    case usage::kX:
      slot = &layout.x;
      break;
    case usage::kY:
      slot = &layout.y;
      break;
    case usage::kTipPressure:
      slot = &layout.pressure;
      break;
    case usage::kXTilt:
      slot = &layout.tilt_x;
      break;
    case usage::kYTilt:
      slot = &layout.tilt_y;
      break;
    case usage::kTwist:
      slot = &layout.twist;
      break;
    case usage::kInRange:
      slot = &layout.in_range;
      break;
    case usage::kTipSwitch:
      slot = &layout.tip;
      break;
    case usage::kBarrelSwitch:
      slot = &layout.barrel1;
      break;
    case usage::kSecondaryBarrelSwitch:
      slot = &layout.barrel2;
      break;
    case usage::kEraser:
      slot = &layout.eraser;
      break;
    case usage::kInvert:
      slot = &layout.invert;
      break;
    default:
      return;
  }
  if (!slot->present()) *slot = axis;
}

// Where the pen's fields may be: in pen collections only, or anywhere but touch collections
// (then X and Y must be absolute and a pressure or tip switch present).
enum class Search { kPenCollections, kAnyCollection };

std::vector<PenReportLayout> find_pen_layouts(const ReportDescriptor& d, Search search,
                                              UsageMap map) {
  std::vector<PenReportLayout> layouts;
  const bool anywhere = search == Search::kAnyCollection;
  // The input fields of each report ID, so that each report visits only its own.
  std::vector<std::vector<std::size_t>> fields_of(256);
  for (std::size_t i = 0; i < d.fields.size(); ++i) {
    const ReportField& field = d.fields[i];
    if (field.type == ReportType::kInput && !field.is_constant() && field.is_variable()) {
      fields_of[field.report_id].push_back(i);
    }
  }
  for (const ReportInfo& report : d.reports) {
    if (report.type != ReportType::kInput) continue;
    PenReportLayout layout;
    layout.report_id = report.report_id;
    layout.bytes = report.bytes(d.has_report_ids);
    layout.outside_pen_collection = anywhere;
    PenAxis buttons[3];
    for (const std::size_t i : fields_of[report.report_id]) {
      const ReportField& field = d.fields[i];
      if (anywhere ? (in_touch_collection(d, field) || field.is_relative())
                   : !in_pen_collection(d, field, map)) {
        continue;
      }
      // Usages beyond the field's elements are never reported; do not walk huge ranges.
      const std::uint32_t n = static_cast<std::uint32_t>(
          std::min<std::uint64_t>(field.count, std::max<std::uint64_t>(field.usage_count(), 1)));
      for (std::uint32_t e = 0; e < n; ++e) {
        const Usage u = map(field.usage_at(e));
        const PenAxis axis = axis_of(field, static_cast<int>(i), e);
        assign(layout, u, axis);
        if (anywhere && usage_page(u) == page::kButton && usage_id(u) >= 1 && usage_id(u) <= 3 &&
            !buttons[usage_id(u) - 1].present()) {
          buttons[usage_id(u) - 1] = axis;
        }
      }
    }
    if (!layout.x.present() || !layout.y.present()) continue;
    if (anywhere) {
      if (!layout.pressure.present() && !layout.tip.present()) continue;
      if (!layout.tip.present()) layout.tip = buttons[0];
      if (!layout.barrel1.present()) layout.barrel1 = buttons[1];
      if (!layout.barrel2.present()) layout.barrel2 = buttons[2];
    }
    layouts.push_back(layout);
  }
  return layouts;
}

struct FoundLayouts {
  std::vector<PenReportLayout> layouts;
  bool wacom_vendor_page = false;
};

// Pen-collection reports first, then pen reports found elsewhere under other report IDs
// (the Huion H610 describes its vendor report 7 as a pen but sends report 9 by default).
FoundLayouts find_any_pen_layouts(const ReportDescriptor& d) {
  std::vector<PenReportLayout> layouts = find_pen_layouts(d, Search::kPenCollections, same_usage);
  for (PenReportLayout& l : find_pen_layouts(d, Search::kAnyCollection, same_usage)) {
    const bool known = std::any_of(layouts.begin(), layouts.end(),
                                   [&](const auto& p) { return p.report_id == l.report_id; });
    if (!known) layouts.push_back(std::move(l));
  }
  if (!layouts.empty()) return {std::move(layouts), false};
  return {find_pen_layouts(d, Search::kPenCollections, wacom_equivalent_usage), true};
}

// mm per logical unit of a position axis, when its unit is a length.
std::optional<double> mm_per_logical(const PenAxis& axis) {
  const std::optional<double> mm = axis.unit.millimetres();
  const std::int64_t logical = axis.logical_max - axis.logical_min;
  const std::int64_t physical = axis.physical_max - axis.physical_min;
  if (!mm || logical <= 0 || physical <= 0) return std::nullopt;
  return *mm * static_cast<double>(physical) / static_cast<double>(logical);
}

// A tilt in degrees: from the unit when it is an angle, else the logical value is taken as
// degrees (what tablets without units send).
double tilt_degrees(const PenAxis& axis, std::int64_t value) {
  if (const auto degrees = axis.unit.degrees()) return axis.physical(value, *degrees);
  return static_cast<double>(value);
}

bool switch_on(const PenAxis& axis, std::span<const std::uint8_t> data, const ReportDescriptor& d) {
  if (!axis.present()) return false;
  const ReportField& field = d.fields[static_cast<std::size_t>(axis.field)];
  return field_value(field, axis.element, data) != 0;
}

}  // namespace

double PenAxis::normalised(std::int64_t value) const {
  if (logical_max <= logical_min) return 0.0;
  const double t =
      static_cast<double>(value - logical_min) / static_cast<double>(logical_max - logical_min);
  return std::clamp(t, 0.0, 1.0);
}

double PenAxis::physical(std::int64_t value, double scale) const {
  if (logical_max == logical_min) return static_cast<double>(physical_min) * scale;
  const double t =
      static_cast<double>(value - logical_min) / static_cast<double>(logical_max - logical_min);
  return (static_cast<double>(physical_min) +
          t * static_cast<double>(physical_max - physical_min)) *
         scale;
}

Usage wacom_equivalent_usage(Usage u) {
  constexpr std::uint16_t kWacomDigitizerPage = 0xFF0D;
  if (usage_page(u) != kWacomDigitizerPage) return u;
  const std::uint16_t sub_page = static_cast<std::uint16_t>(usage_id(u) >> 8);
  return make_usage(sub_page == 0 ? page::kDigitizer : sub_page, usage_id(u) & 0xFF);
}

std::string unsupported_reason(const ReportDescriptor& descriptor) {
  if (!find_any_pen_layouts(descriptor).layouts.empty()) return "";
  const auto vendor_defined = [](std::uint16_t page, const std::string& where) {
    return "its pen reports are vendor-defined (" + where + usage_page_name(page) +
           "); Impasto reads only standard HID digitizer reports";
  };
  // Vendor usages inside a digitizer collection (the Wacom PenPartner) ...
  for (const ReportField& f : descriptor.fields) {
    if (f.type != ReportType::kInput || f.is_constant() || f.usages.empty()) continue;
    const std::uint16_t page = usage_page(f.usage_at(0));
    if (page >= page::kVendorFirst && in_pen_collection(descriptor, f, same_usage)) {
      return vendor_defined(page, "usage page ");
    }
  }
  // ... or a whole vendor-defined application collection (the Wacom Intuos S 3rd gen).
  for (const Collection& c : descriptor.collections) {
    if (c.parent < 0 && usage_page(c.usage) >= page::kVendorFirst) {
      return vendor_defined(usage_page(c.usage), "application collection of ");
    }
  }
  return "it has no pen report (X and Y in a Digitizer Pen or Stylus collection, or absolute "
         "X, Y and Tip Pressure or Tip Switch in any other)";
}

PenDecoder::PenDecoder(ReportDescriptor descriptor, DecoderOptions options)
    : descriptor_(std::move(descriptor)), options_(options) {
  FoundLayouts found = find_any_pen_layouts(descriptor_);
  layouts_ = std::move(found.layouts);
  wacom_vendor_page_ = found.wacom_vendor_page;
  if (layouts_.empty())
    throw UnsupportedTablet("unsupported tablet: " + unsupported_reason(descriptor_));
  if (!(options_.fallback_lines_per_mm > 0.0)) {
    throw std::invalid_argument("fallback_lines_per_mm must be positive");
  }
  // Each report scales its own extents: a tablet's default and full-resolution reports
  // differ.
  for (PenReportLayout& l : layouts_) {
    const auto x = mm_per_logical(l.x);
    const auto y = mm_per_logical(l.y);
    const std::int64_t span_x = l.x.logical_max - l.x.logical_min;
    const std::int64_t span_y = l.y.logical_max - l.y.logical_min;
    const bool known = options_.known_width_mm && options_.known_height_mm &&
                       *options_.known_width_mm > 0.0 && *options_.known_height_mm > 0.0 &&
                       span_x > 0 && span_y > 0;
    l.area_from_descriptor = x.has_value() && y.has_value();
    l.area_from_model = !l.area_from_descriptor && known;
    if (l.area_from_model) {
      l.mm_per_x = *options_.known_width_mm / static_cast<double>(span_x);
      l.mm_per_y = *options_.known_height_mm / static_cast<double>(span_y);
    } else {
      l.mm_per_x = x.value_or(1.0 / options_.fallback_lines_per_mm);
      l.mm_per_y = y.value_or(1.0 / options_.fallback_lines_per_mm);
    }
  }
  // A report without length units (the Huion H610's report 9, 0..2048) spans the same
  // surface as a report of the descriptor that states its area (its report 7, in inches).
  const auto stated = std::find_if(layouts_.begin(), layouts_.end(),
                                   [](const PenReportLayout& l) { return l.area_from_descriptor; });
  if (stated != layouts_.end()) {
    const double width =
        static_cast<double>(stated->x.logical_max - stated->x.logical_min) * stated->mm_per_x;
    const double height =
        static_cast<double>(stated->y.logical_max - stated->y.logical_min) * stated->mm_per_y;
    for (PenReportLayout& l : layouts_) {
      const std::int64_t span_x = l.x.logical_max - l.x.logical_min;
      const std::int64_t span_y = l.y.logical_max - l.y.logical_min;
      if (l.area_from_descriptor || l.area_from_model || span_x <= 0 || span_y <= 0) continue;
      l.mm_per_x = width / static_cast<double>(span_x);
      l.mm_per_y = height / static_cast<double>(span_y);
      l.area_from_descriptor = true;
    }
  }
  const PenReportLayout& first = layouts_.front();
  area_.from_descriptor = first.area_from_descriptor;
  area_.from_model = first.area_from_model;
  area_.width_mm = static_cast<double>(first.x.logical_max - first.x.logical_min) * first.mm_per_x;
  area_.height_mm = static_cast<double>(first.y.logical_max - first.y.logical_min) * first.mm_per_y;
  pressure_max_.clear();
  for (const PenReportLayout& l : layouts_) pressure_max_.push_back(l.pressure.logical_max);
}

namespace {

// The pressure range a value past the declared maximum shows: the model's maximum when it
// holds the value, else the smallest 2^k - 1 that does (within the field's bits).
std::int64_t grown_pressure_max(std::int64_t value, const PenAxis& axis,
                                std::optional<std::int64_t> model_max) {
  if (model_max && *model_max >= value) return *model_max;
  std::int64_t full = std::max<std::int64_t>(axis.logical_max, 1);
  while (full < value && full < (std::int64_t{1} << 40)) full = 2 * full + 1;
  return std::max(full, value);
}

}  // namespace

std::int64_t PenDecoder::pressure_max(std::uint8_t report_id) const {
  for (std::size_t i = 0; i < layouts_.size(); ++i) {
    if (report_id == 0 || layouts_[i].report_id == report_id) return pressure_max_[i];
  }
  return 0;
}

std::optional<PenSample> PenDecoder::decode(std::span<const std::uint8_t> report, double time_s,
                                            const std::string& source) const {
  if (report.empty()) return std::nullopt;
  const std::uint8_t id = descriptor_.has_report_ids ? report[0] : 0;
  const PenReportLayout* layout = nullptr;
  for (const PenReportLayout& l : layouts_) {
    if (l.report_id == id) layout = &l;
  }
  if (layout == nullptr) return std::nullopt;
  if (report.size() < layout->bytes) {
    throw InputFormatError(source, 0, "length",
                           "pen report " + std::to_string(id) + " has " +
                               std::to_string(report.size()) + " bytes, the descriptor declares " +
                               std::to_string(layout->bytes));
  }
  const ReportView view{id, descriptor_.has_report_ids ? report.subspan(1) : report};
  const auto value = [&](const PenAxis& axis) {
    return field_value(descriptor_.fields[static_cast<std::size_t>(axis.field)], axis.element,
                       view.data);
  };

  PenSample s;
  s.time_s = time_s;
  s.x_mm = static_cast<double>(value(layout->x) - layout->x.logical_min) * layout->mm_per_x;
  s.y_mm = static_cast<double>(value(layout->y) - layout->y.logical_min) * layout->mm_per_y;
  if (layout->pressure.present()) {
    const std::int64_t raw = value(layout->pressure);
    std::int64_t& full = pressure_max_[static_cast<std::size_t>(layout - layouts_.data())];
    if (raw > full) full = grown_pressure_max(raw, layout->pressure, options_.known_max_pressure);
    PenAxis pressure = layout->pressure;
    pressure.logical_max = full;
    s.pressure = static_cast<float>(pressure.normalised(raw));
  }
  if (layout->tilt_x.present()) {
    s.tilt_x_deg = static_cast<float>(
        std::clamp(tilt_degrees(layout->tilt_x, value(layout->tilt_x)), -90.0, 90.0));
  }
  if (layout->tilt_y.present()) {
    s.tilt_y_deg = static_cast<float>(
        std::clamp(tilt_degrees(layout->tilt_y, value(layout->tilt_y)), -90.0, 90.0));
  }
  if (layout->twist.present()) {
    const auto degrees = layout->twist.unit.degrees();
    double twist = degrees ? layout->twist.physical(value(layout->twist), *degrees)
                           : 360.0 * layout->twist.normalised(value(layout->twist));
    twist = std::fmod(twist, 360.0);
    if (twist < 0.0) twist += 360.0;
    s.rotation_deg = static_cast<float>(twist);
  }
  const bool tip =
      layout->tip.present() ? switch_on(layout->tip, view.data, descriptor_) : s.pressure > 0.0f;
  // Without an In Range usage, a pen report means the pen is in range.
  const bool in_range =
      !layout->in_range.present() || switch_on(layout->in_range, view.data, descriptor_) || tip;
  std::uint32_t buttons = 0;
  if (tip) buttons |= paintcore::kPenTip;
  if (in_range) buttons |= paintcore::kPenInRange;
  if (switch_on(layout->barrel1, view.data, descriptor_)) buttons |= paintcore::kPenBarrel1;
  if (switch_on(layout->barrel2, view.data, descriptor_)) buttons |= paintcore::kPenBarrel2;
  if (switch_on(layout->eraser, view.data, descriptor_) ||
      switch_on(layout->invert, view.data, descriptor_)) {
    buttons |= paintcore::kPenEraser;
  }
  s.buttons = buttons;
  return s;
}

}  // namespace impasto::input::hid
