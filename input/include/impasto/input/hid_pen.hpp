#pragma once
// Turning a tablet's HID input reports into pen samples: which fields of which reports carry
// the pen's position, pressure, tilt, twist and switches, and how to scale them.
#include <impasto/input/hid_descriptor.hpp>
#include <impasto/paintcore/pen_sample.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace impasto::input::hid {

// A tablet whose descriptor has no standard pen report (for example one whose pen speaks
// only vendor-defined reports). The message says why.
class UnsupportedTablet : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One value of a pen report: a field element and its extents.
struct PenAxis {
  int field = -1;  // index into ReportDescriptor::fields; -1 when the report lacks it
  std::uint32_t element = 0;
  std::int64_t logical_min = 0;
  std::int64_t logical_max = 0;
  std::int64_t physical_min = 0;
  std::int64_t physical_max = 0;
  Unit unit;

  bool present() const { return field >= 0; }
  // The value as a fraction of the logical range, clamped to 0..1.
  double normalised(std::int64_t value) const;
  // The value in physical units times `scale` (e.g. mm per unit), linear in the logical value.
  double physical(std::int64_t value, double scale) const;
};

// Where one pen report keeps each quantity.
struct PenReportLayout {
  std::uint8_t report_id = 0;
  std::size_t bytes = 0;  // on the wire, report ID included
  PenAxis x, y, pressure, tilt_x, tilt_y, twist;
  PenAxis in_range, tip, barrel1, barrel2, eraser, invert;
  // Found outside any pen collection (a Huion's "mouse" report 9): Button 1..3 stand for the
  // tip and the two barrel buttons.
  bool outside_pen_collection = false;
  // mm per logical unit of x and y, and where the scale came from.
  double mm_per_x = 0.0;
  double mm_per_y = 0.0;
  bool area_from_descriptor = false;
  bool area_from_model = false;
};

struct DecoderOptions {
  // When the descriptor gives no usable length unit for X and Y, logical units are taken
  // as this many per mm (100 is common: 2540 lines per inch).
  double fallback_lines_per_mm = 100.0;
  // The active area from elsewhere (the model table, a vendor handshake): used instead of
  // the fallback when the descriptor's X and Y units are not lengths.
  std::optional<double> known_width_mm;
  std::optional<double> known_height_mm;
  // The pressure levels the model table gives (its largest raw value): where a report's
  // pressure passes the descriptor's maximum, the range grows to this (see PenDecoder).
  std::optional<std::int64_t> known_max_pressure;
};

// The tablet's active area in mm, and whether the descriptor stated it.
struct TabletArea {
  double width_mm = 0.0;
  double height_mm = 0.0;
  bool from_descriptor = false;
  bool from_model = false;  // from DecoderOptions' known area
};

class PenDecoder {
 public:
  // Finds the pen reports: input reports with X and Y in a Digitizer Pen or Digitizer
  // application collection or in a Stylus collection; else input reports with absolute X
  // and Y plus Tip Pressure or a Tip Switch in any collection but a touch one; else the
  // same in Wacom's vendor page 0xFF0D, mapped to the standard usages as the Linux wacom
  // driver maps them. Throws UnsupportedTablet if none.
  explicit PenDecoder(ReportDescriptor descriptor, DecoderOptions options = {});

  // Decodes one raw input report taken at time_s. Reports that are not pen reports (pad
  // buttons, vendor reports) give nullopt. Positions are mm on the tablet from the top left
  // of its active area. Throws InputFormatError, naming `source`, for a pen report shorter
  // than declared.
  //
  // Some tablets send more pressure than their descriptor declares (an XP-Pen Deco 01 v2 in
  // its default mode: up to 8191 where it says 2047, so every press past a quarter read as
  // full). The first value past the declared maximum grows that report's range, for good, to
  // the model table's maximum if it holds the value, else to the smallest 2^k - 1 that does
  // (what the field's bits allow); pressure_max() says where it stands.
  std::optional<paintcore::PenSample> decode(std::span<const std::uint8_t> report, double time_s,
                                             const std::string& source = "report") const;

  const ReportDescriptor& descriptor() const { return descriptor_; }
  const std::vector<PenReportLayout>& layouts() const { return layouts_; }
  TabletArea area() const { return area_; }
  // Whether the pen was found through Wacom's vendor usages (0xFF0D).
  bool wacom_vendor_page() const { return wacom_vendor_page_; }
  // The raw pressure read as full for the report with `report_id` (0: the first pen report):
  // the descriptor's maximum, or the range a report showed it to have.
  std::int64_t pressure_max(std::uint8_t report_id = 0) const;
  // Of the first pen report (each layout has its own).
  double mm_per_logical_x() const { return layouts_.front().mm_per_x; }
  double mm_per_logical_y() const { return layouts_.front().mm_per_y; }

 private:
  ReportDescriptor descriptor_;
  std::vector<PenReportLayout> layouts_;
  DecoderOptions options_;
  TabletArea area_;
  bool wacom_vendor_page_ = false;
  // Per layout, the pressure range the reports have shown (grown from the declared one).
  mutable std::vector<std::int64_t> pressure_max_;
};

// The standard usage a Wacom vendor usage stands for (Linux's wacom_equivalent_usage):
// 0xFF0D00uu -> Digitizer 0x00uu, 0xFF0Dppuu -> page pp usage uu; others unchanged.
Usage wacom_equivalent_usage(Usage u);

// Why a descriptor has no pen report, or an empty string when it has one.
std::string unsupported_reason(const ReportDescriptor& descriptor);

}  // namespace impasto::input::hid
