#pragma once
// Flake paints shared by the flake tests: the shipped files and small hand-made ones.
#include <filesystem>
#include <numbers>
#include <string>

#include "impasto/flakes/flake_file.hpp"

namespace impasto::flakes::test {

inline std::filesystem::path flake_data_dir() {
  return std::filesystem::path(IMPASTO_SOURCE_DIR) / "data" / "flakes";
}

inline FlakePaint shipped_aluminium() {
  return load_flake_paint(flake_data_dir() / "aluminium_flakes.flake");
}

inline FlakePaint shipped_pearl() {
  return load_flake_paint(flake_data_dir() / "mica_tio2_blue_pearl.flake");
}

// A grey metal (n, k the same at every wavelength) in a binder of index eta, without
// binder absorption or pigment scattering.
inline FlakePaint grey_metal_paint(double eta, double sd_deg = 10.0) {
  FlakePaint paint;
  paint.name = "grey";
  paint.area_density_per_mm = 40;
  paint.flake_area_mean_mm2 = 3e-4;
  paint.flake_area_sd_mm2 = 1e-4;
  paint.orientation.kind = OrientationDistribution::Kind::gaussian;
  paint.orientation.gaussian_sd_rad = sd_deg * std::numbers::pi / 180.0;
  paint.coating = parse_nk_table("wavelength_nm,n,k\n300,1.2,7\n900,1.2,7\n", "grey.csv");
  paint.binder_index = eta;
  return paint;
}

}  // namespace impasto::flakes::test
