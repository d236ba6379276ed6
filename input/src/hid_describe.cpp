#include <impasto/input/hid_describe.hpp>

#include <cstdio>
#include <sstream>

namespace impasto::input::hid {

namespace {

std::string usages_text(const ReportField& field) {
  if (field.usages.empty()) return field.is_constant() ? "(padding)" : "(no usage)";
  std::string text;
  for (const UsageRange& r : field.usages) {
    if (!text.empty()) text += ", ";
    text += usage_name(r.first);
    if (r.last != r.first) text += " .. " + usage_name(r.last);
  }
  return text;
}

std::string flags_text(const ReportField& field) {
  std::string text = field.is_constant() ? "Const" : "Data";
  text += field.is_variable() ? ",Var" : ",Array";
  text += field.is_relative() ? ",Rel" : ",Abs";
  if (field.has_null_state()) text += ",Null";
  return text;
}

std::string mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f mm", value);
  return text;
}

}  // namespace

std::string describe_reports(const ReportDescriptor& d) {
  std::ostringstream out;
  out << "report IDs: " << (d.has_report_ids ? "yes" : "no") << ", " << d.collections.size()
      << " collections, " << d.reports.size() << " reports\n";
  for (const ReportInfo& report : d.reports) {
    out << report_type_name(report.type) << " report " << int{report.report_id} << ": "
        << report.bytes(d.has_report_ids) << " bytes (" << (d.has_report_ids ? "ID byte + " : "")
        << report.bits << " bits)";
    const Usage application = [&] {
      for (const ReportField& f : d.fields) {
        if (f.type == report.type && f.report_id == report.report_id) return d.application_of(f);
      }
      return Usage{0};
    }();
    if (application != 0) out << " in " << usage_name(application);
    out << "\n";
    for (const ReportField& f : d.fields) {
      if (f.type != report.type || f.report_id != report.report_id) continue;
      out << "  bit " << f.bit_offset << ": " << f.bit_size << " x " << f.count << " "
          << flags_text(f) << "  " << usages_text(f);
      if (!f.is_constant()) {
        out << "  logical " << f.logical_min << ".." << f.logical_max;
        if (f.physical_min != f.logical_min || f.physical_max != f.logical_max) {
          out << " physical " << f.physical_min << ".." << f.physical_max;
        }
        if (f.unit.code != 0) out << " unit " << f.unit.name();
      }
      out << "\n";
    }
  }
  return out.str();
}

std::string describe_pen(const PenDecoder& decoder) {
  std::ostringstream out;
  const TabletArea area = decoder.area();
  out << "active area " << mm(area.width_mm) << " x " << mm(area.height_mm)
      << (area.from_descriptor ? ""
          : area.from_model    ? " (from the model table or handshake)"
                               : " (no length unit in the descriptor: assumed)")
      << (decoder.wacom_vendor_page() ? ", Wacom vendor usages (0xFF0D) mapped" : "") << "\n";
  for (const PenReportLayout& l : decoder.layouts()) {
    out << "pen report " << int{l.report_id} << " (" << l.bytes << " bytes"
        << (l.outside_pen_collection ? ", outside a pen collection" : "") << "):";
    out << " x 0.." << l.x.logical_max << ", y 0.." << l.y.logical_max;
    if (l.pressure.present()) {
      out << ", pressure " << (l.pressure.logical_max - l.pressure.logical_min + 1) << " levels";
    }
    if (l.tilt_x.present())
      out << ", tilt x " << l.tilt_x.logical_min << ".." << l.tilt_x.logical_max;
    if (l.tilt_y.present())
      out << ", tilt y " << l.tilt_y.logical_min << ".." << l.tilt_y.logical_max;
    if (l.twist.present()) out << ", twist";
    out << "; switches:";
    if (l.tip.present()) out << " tip";
    if (l.in_range.present()) out << " in-range";
    if (l.barrel1.present()) out << " barrel";
    if (l.barrel2.present()) out << " barrel2";
    if (l.eraser.present()) out << " eraser";
    if (l.invert.present()) out << " invert";
    out << "\n";
  }
  return out.str();
}

std::string describe_tablet_list(const std::vector<PenTabletInfo>& tablets) {
  std::ostringstream out;
  for (const PenTabletInfo& t : tablets) {
    char ids[16];
    std::snprintf(ids, sizeof ids, "%04x:%04x", t.device.vendor_id, t.device.product_id);
    out << t.device.path << "  " << ids << "  " << t.device.manufacturer
        << (t.device.manufacturer.empty() ? "" : " ") << t.device.product << "\n";
    if (!t.unsupported_reason.empty() || !t.summary) {
      out << "  unsupported: " << t.unsupported_reason << "\n";
      continue;
    }
    const TabletSummary& s = *t.summary;
    char line[200];
    std::snprintf(line, sizeof line, "%.2f x %.2f mm%s", s.width_mm, s.height_mm,
                  s.area_known ? "" : " (assumed)");
    out << "  vendor: " << (s.vendor.empty() ? "unknown" : s.vendor)
        << "  model: " << (s.model.empty() ? "unknown" : s.model) << "\n"
        << "  protocol: " << s.protocol << "  area: " << line << "  pressure: ";
    if (s.pressure_levels > 0) {
      out << s.pressure_levels << " levels";
    } else {
      out << "none";
    }
    out << "  tilt: " << (s.tilt ? "yes" : "no") << "\n";
    if (!t.readable) out << "  no permission to read " << t.device.path << "\n";
  }
  return out.str();
}

}  // namespace impasto::input::hid
