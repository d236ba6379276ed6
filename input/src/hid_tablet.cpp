#include <impasto/input/hid_tablet.hpp>

#include <impasto/input/hid_describe.hpp>

#include <cstdio>

namespace impasto::input::hid {

namespace {

std::uint32_t pressure_levels(const PenDecoder& pen) {
  const PenAxis& p = pen.layouts().front().pressure;
  return p.present() ? static_cast<std::uint32_t>(p.logical_max - p.logical_min + 1) : 0;
}

}  // namespace

std::string tablet_vendor_name(std::uint16_t vendor_id) {
  switch (vendor_id) {
    case 0x056A:
      return "Wacom";
    case 0x256C:
      return "Huion / Gaomon";
    case 0x28BD:
      return "XP-Pen / Ugee";
    case 0x5543:
      return "UC-Logic";
    case 0x2FEB:
      return "Veikk";
    default:
      return "";
  }
}

TabletDecoder::TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                             std::uint16_t product_id, DecoderOptions options)
    : TabletDecoder(descriptor, vendor_id, product_id, InitExchange{}, default_tablet_models(),
                    options) {}

TabletDecoder::TabletDecoder(std::span<const std::uint8_t> descriptor, std::uint16_t vendor_id,
                             std::uint16_t product_id, const InitExchange& init,
                             const std::vector<TabletModel>& models, DecoderOptions options) {
  summary_.vendor = tablet_vendor_name(vendor_id);
  if (const auto graphire = find_graphire_tablet(vendor_id, product_id)) {
    graphire_ = *graphire;
    summary_.model = graphire->name;
    summary_.protocol = "Wacom Graphire";
    summary_.width_mm = graphire->max_x / graphire->lines_per_mm;
    summary_.height_mm = graphire->max_y / graphire->lines_per_mm;
    summary_.area_known = true;
    summary_.pressure_levels = static_cast<std::uint32_t>(graphire->max_pressure + 1);
    return;
  }

  // The model table's rows for this tablet; several when models share ids and the
  // handshake did not tell them apart.
  const std::vector<TabletModel> rows = find_tablet_models(models, vendor_id, product_id, init);
  for (const TabletModel& m : rows) {
    if (summary_.model.find(m.name) != std::string::npos) continue;
    summary_.model += (summary_.model.empty() ? "" : " / ") + m.name;
  }
  const TabletModel* model = rows.empty() ? nullptr : &rows.front();

  // UC-Logic tablets (and unknown models of their vendors) answer their extents in the
  // handshake; the tablet's own answer wins over the table.
  const bool uclogic =
      model ? model->protocol == ModelProtocol::kUcLogic : is_uclogic_vendor(vendor_id);
  if (uclogic) {
    if (const auto params = uclogic_params(init)) {
      vendor_ = uclogic_format(*params);
      vendor_first_ = true;
      if (vendor_->width_mm <= 0.0 && model) {  // no resolution in the answer
        vendor_->width_mm = model->width_mm;
        vendor_->height_mm = model->height_mm;
      }
      if (model) vendor_->tilt = vendor_->tilt || model->tilt;
    }
  }
  if (!vendor_ && model) vendor_ = model->vendor_format();
  if (vendor_) {
    summary_.protocol = std::string(vendor_protocol_name(vendor_->protocol)) +
                        (vendor_first_ ? " (handshake)" : " (model table)");
    summary_.width_mm = vendor_->width_mm;
    summary_.height_mm = vendor_->height_mm;
    summary_.area_known = vendor_->width_mm > 0.0;
    summary_.pressure_levels = vendor_->max_pressure + 1;
    summary_.tilt = vendor_->tilt;
    // The descriptor's own pen reports, when their units are not lengths, span this area.
    if (vendor_->width_mm > 0.0) {
      options.known_width_mm = vendor_->width_mm;
      options.known_height_mm = vendor_->height_mm;
    }
  } else if (model) {
    options.known_width_mm = model->width_mm;
    options.known_height_mm = model->height_mm;
  }
  if (model && model->max_pressure > 0) options.known_max_pressure = model->max_pressure;

  try {
    pen_.emplace(parse_report_descriptor(descriptor, "device descriptor"), options);
  } catch (const UnsupportedTablet&) {
    if (!vendor_) throw;
  } catch (const InputFormatError&) {
    if (!vendor_) throw;
  }
  if (pen_ && !vendor_first_) {
    const TabletArea a = pen_->area();
    summary_.protocol =
        std::string("HID descriptor") +
        (pen_->wacom_vendor_page() ? " (Wacom vendor page 0xFF0D)" : "") +
        (pen_->layouts().front().outside_pen_collection ? " (pen outside a pen collection)" : "") +
        (vendor_ ? std::string(" + ") + vendor_protocol_name(vendor_->protocol) : "");
    summary_.width_mm = a.width_mm;
    summary_.height_mm = a.height_mm;
    summary_.area_known = a.from_descriptor || a.from_model;
    summary_.pressure_levels = pressure_levels(*pen_);
    const PenReportLayout& l = pen_->layouts().front();
    summary_.tilt = l.tilt_x.present() || l.tilt_y.present();
  }
}

std::optional<paintcore::PenSample> TabletDecoder::decode(std::span<const std::uint8_t> report,
                                                          double time_s,
                                                          const std::string& source) const {
  if (graphire_) return decode_graphire_report(*graphire_, report, time_s);
  if (vendor_ && !report.empty() && report[0] == vendor_->report_id()) {
    // Without a handshake, the descriptor's own description of the report comes first.
    if (vendor_first_ || !describes_report(report[0]))
      return decode_vendor_pen_report(*vendor_, report, time_s);
  }
  if (pen_) return pen_->decode(report, time_s, source);
  return std::nullopt;
}

bool TabletDecoder::describes_report(std::uint8_t report_id) const {
  if (!pen_) return false;
  for (const PenReportLayout& l : pen_->layouts()) {
    if (l.report_id == report_id) return true;
  }
  return false;
}

TabletArea TabletDecoder::area() const {
  if (pen_ && !vendor_first_) return pen_->area();
  return {summary_.width_mm, summary_.height_mm, false, summary_.area_known};
}

std::string TabletDecoder::describe() const {
  char text[400];
  std::snprintf(text, sizeof text,
                "%s%s%s: protocol %s, active area %.2f mm x %.2f mm%s, pressure %u levels, "
                "tilt %s\n",
                summary_.vendor.empty() ? "unknown vendor" : summary_.vendor.c_str(),
                summary_.model.empty() ? "" : ", ", summary_.model.c_str(),
                summary_.protocol.c_str(), summary_.width_mm, summary_.height_mm,
                summary_.area_known ? "" : " (assumed)", summary_.pressure_levels,
                summary_.tilt ? "yes" : "no");
  std::string out = text;
  if (pen_ && !vendor_first_) out += describe_pen(*pen_);
  return out;
}

}  // namespace impasto::input::hid
