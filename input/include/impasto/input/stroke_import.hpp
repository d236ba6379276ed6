#pragma once
// Importers for stroke recordings made by other programs, and one call that loads any of them.
#include <impasto/input/stroke_error.hpp>
#include <impasto/input/stroke_events.hpp>

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace impasto::input {

struct ImportOptions {
  // Pixels per inch of the source of a libmypaint .dat file (px -> mm).
  double source_dpi = 150.0;
  // Full-scale pressure of a BDALab .svc file in device units; unset: the file's maximum.
  std::optional<double> pressure_max;
};

// libmypaint's event files: "time_s x_px y_px pressure" per line. A stroke ends where the
// pressure drops to 0 (tip bit cleared); every sample is in range. No tilt.
StrokeFile parse_mypaint_dat(std::istream& in, const std::string& source_name,
                             const ImportOptions& options = {});

// BDALab's .svc: a sample count, then "x_mm y_mm time_s pen_down azimuth altitude pressure"
// with angles in 0.1 degree units. Azimuth (clockwise from the file's +y axis) and altitude
// (above the surface) become tilt towards the file's +x and +y.
StrokeFile parse_bdalab_svc(std::istream& in, const std::string& source_name,
                            const ImportOptions& options = {});

// Tilt towards +x and +y in degrees of a pen at the given azimuth and altitude (degrees).
struct Tilt {
  double x_deg = 0.0;
  double y_deg = 0.0;
};
Tilt tilt_from_azimuth_altitude(double azimuth_deg, double altitude_deg);

enum class StrokeFileKind { kNative, kMypaintDat, kBdalabSvc };

// Guesses the kind of a file from its first line, then its extension.
StrokeFileKind detect_stroke_file_kind(const std::filesystem::path& path);

// Loads a native, .dat or .svc file; errors name the file and line.
StrokeFile load_strokes_any(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace impasto::input
