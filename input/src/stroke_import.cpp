#include <impasto/input/stroke_import.hpp>

#include <impasto/input/stroke_file.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include "recording_input.hpp"
#include "text_fields.hpp"

namespace impasto::input {

namespace {

using paintcore::PenSample;

constexpr double kMmPerInch = 25.4;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kRadPerDeg = std::numbers::pi / 180.0;

void check_time_order(double time_s, double previous_s, bool first,
                      const detail::LineContext& where) {
  if (!first && time_s < previous_s) where.fail("time", "time goes backwards");
}

// Calls visit(fields, where) for each non-blank line of `in` after line `line_number` (which it
// advances), each line's fields numbering `columns`: the rows of the importers' column files.
template <class Visit>
void for_each_row(std::istream& in, const std::string& source_name, int& line_number,
                  std::size_t columns, const std::string& column_names, Visit&& visit) {
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const detail::LineContext where{source_name, line_number};
    const auto fields = detail::split_fields(line, where);
    if (fields.empty()) continue;
    if (fields.size() != columns) {
      where.fail("", "expected " + std::to_string(columns) + " columns (" + column_names +
                         "), found " + std::to_string(fields.size()));
    }
    visit(fields, where);
  }
}

}  // namespace

StrokeFile parse_mypaint_dat(std::istream& in, const std::string& source_name,
                             const ImportOptions& options) {
  if (!(options.source_dpi > 0.0) || !std::isfinite(options.source_dpi)) {
    throw InputFormatError(source_name, 0, "dpi", "source dpi must be a positive number");
  }
  const double mm_per_px = kMmPerInch / options.source_dpi;
  StrokeFile file;
  int line_number = 0;
  double previous_time_s = 0.0;
  for_each_row(in, source_name, line_number, 4, "time x y pressure",
               [&](const std::vector<std::string_view>& fields, const detail::LineContext& where) {
                 PenSample s;
                 s.time_s = detail::parse_double(fields[0], where, "time");
                 s.x_mm = detail::parse_double(fields[1], where, "x") * mm_per_px;
                 s.y_mm = detail::parse_double(fields[2], where, "y") * mm_per_px;
                 const double pressure = detail::parse_double(fields[3], where, "pressure");
                 if (pressure < 0.0 || pressure > 1.0) where.fail("pressure", "outside 0..1");
                 check_time_order(s.time_s, previous_time_s, file.events.empty(), where);
                 previous_time_s = s.time_s;
                 s.pressure = static_cast<float>(pressure);
                 s.buttons = paintcore::kPenInRange | (pressure > 0.0 ? paintcore::kPenTip : 0u);
                 file.events.push_back(SampleEvent{s});
               });
  if (file.events.empty()) throw InputFormatError(source_name, 0, "", "no samples");
  return file;
}

Tilt tilt_from_azimuth_altitude(double azimuth_deg, double altitude_deg) {
  // The pen's direction from tip to end: horizontal part cos(alt) along the azimuth,
  // vertical part sin(alt). Its tilt towards an axis is the angle from the vertical as seen
  // in the plane of that axis and the vertical.
  const double az = azimuth_deg * kRadPerDeg;
  const double alt = altitude_deg * kRadPerDeg;
  const double horizontal = std::cos(alt);
  const double vertical = std::sin(alt);
  return {std::atan2(horizontal * std::sin(az), vertical) * kDegPerRad,
          std::atan2(horizontal * std::cos(az), vertical) * kDegPerRad};
}

StrokeFile parse_bdalab_svc(std::istream& in, const std::string& source_name,
                            const ImportOptions& options) {
  std::string line;
  int line_number = 0;
  std::int64_t declared = -1;
  while (declared < 0 && std::getline(in, line)) {
    ++line_number;
    const detail::LineContext where{source_name, line_number};
    const auto fields = detail::split_fields(line, where);
    if (fields.empty()) continue;
    if (fields.size() != 1) where.fail("count", "the first line must be the sample count");
    declared = detail::parse_integer(fields[0], where, "count");
    if (declared < 0) where.fail("count", "negative sample count");
  }
  if (declared < 0) throw InputFormatError(source_name, 1, "count", "empty file");

  struct Raw {
    PenSample sample;
    double pressure_units = 0.0;
  };
  std::vector<Raw> raw;
  double previous_time_s = 0.0;
  for_each_row(
      in, source_name, line_number, 7, "x y time pen_down azimuth altitude pressure",
      [&](const std::vector<std::string_view>& fields, const detail::LineContext& where) {
        Raw r;
        PenSample& s = r.sample;
        s.x_mm = detail::parse_double(fields[0], where, "x");
        s.y_mm = detail::parse_double(fields[1], where, "y");
        s.time_s = detail::parse_double(fields[2], where, "time");
        check_time_order(s.time_s, previous_time_s, raw.empty(), where);
        previous_time_s = s.time_s;
        const double pen_down = detail::parse_double(fields[3], where, "pen_down");
        if (pen_down != 0.0 && pen_down != 1.0) where.fail("pen_down", "must be 0 or 1");
        const double azimuth_deg = detail::parse_double(fields[4], where, "azimuth") / 10.0;
        const double altitude_deg = detail::parse_double(fields[5], where, "altitude") / 10.0;
        if (altitude_deg < 0.0 || altitude_deg > 90.0) where.fail("altitude", "outside 0..900");
        // An angle in tenths of a degree: one turn either way (the recordings give 0..3599).
        if (azimuth_deg < -360.0 || azimuth_deg > 360.0)
          where.fail("azimuth", "outside -3600..3600");
        const Tilt tilt = tilt_from_azimuth_altitude(azimuth_deg, altitude_deg);
        s.tilt_x_deg = static_cast<float>(tilt.x_deg);
        s.tilt_y_deg = static_cast<float>(tilt.y_deg);
        r.pressure_units = detail::parse_double(fields[6], where, "pressure");
        if (r.pressure_units < 0.0) where.fail("pressure", "negative pressure");
        s.buttons = paintcore::kPenInRange | (pen_down == 1.0 ? paintcore::kPenTip : 0u);
        raw.push_back(r);
      });
  // Public datasets hold files whose count is off by one from their lines (a header counted,
  // a last line lost): the lines present are read, with a warning. More is an error.
  const std::int64_t present = static_cast<std::int64_t>(raw.size());
  std::string count_warning;
  if (present != declared) {
    const std::string mismatch = "declares " + std::to_string(declared) +
                                 " samples but the file has " + std::to_string(present);
    if (present == 0 || (present != declared + 1 && present != declared - 1)) {
      throw InputFormatError(source_name, 1, "count", mismatch);
    }
    count_warning = source_name + ":1: field 'count': " + mismatch + "; the " +
                    std::to_string(present) + " present are used";
  }

  double full_scale = 0.0;
  if (options.pressure_max) {
    full_scale = *options.pressure_max;
    if (!(full_scale > 0.0) || !std::isfinite(full_scale)) {
      throw InputFormatError(source_name, 0, "pressure", "the given maximum must be positive");
    }
  } else {
    for (const Raw& r : raw) full_scale = std::max(full_scale, r.pressure_units);
  }
  StrokeFile file;
  file.events.reserve(raw.size());
  for (Raw& r : raw) {
    const double p = full_scale > 0.0 ? r.pressure_units / full_scale : 0.0;
    r.sample.pressure = static_cast<float>(std::clamp(p, 0.0, 1.0));
    file.events.push_back(SampleEvent{r.sample});
  }
  if (!count_warning.empty()) file.warnings.push_back(count_warning);
  return file;
}

StrokeFileKind detect_stroke_file_kind(const std::filesystem::path& path) {
  const auto in = detail::open_recording(path, "stroke file");
  std::string first;
  std::getline(in->stream(), first);
  if (first.rfind("impasto-strokes", 0) == 0) return StrokeFileKind::kNative;
  const std::string ext = path.extension().string();
  if (ext == ".dat") return StrokeFileKind::kMypaintDat;
  if (ext == ".svc") return StrokeFileKind::kBdalabSvc;
  // No telling extension: a lone integer starts an .svc, four numbers a .dat.
  const std::string source = path.string();
  const detail::LineContext where{source, 1};
  std::vector<std::string_view> fields;
  try {
    fields = detail::split_fields(first, where);
  } catch (const InputFormatError&) {
  }
  if (fields.size() == 1) return StrokeFileKind::kBdalabSvc;
  if (fields.size() == 4) return StrokeFileKind::kMypaintDat;
  throw InputFormatError(source, 1, "",
                         "unknown stroke file kind (expected an Impasto stroke file, a "
                         "libmypaint .dat or a BDALab .svc)");
}

StrokeFile load_strokes_any(const std::filesystem::path& path, const ImportOptions& options) {
  const StrokeFileKind kind = detect_stroke_file_kind(path);
  if (kind == StrokeFileKind::kNative) return read_stroke_file(path);
  const auto in = detail::open_recording(path, "stroke file");
  if (kind == StrokeFileKind::kMypaintDat)
    return parse_mypaint_dat(in->stream(), path.string(), options);
  return parse_bdalab_svc(in->stream(), path.string(), options);
}

}  // namespace impasto::input
