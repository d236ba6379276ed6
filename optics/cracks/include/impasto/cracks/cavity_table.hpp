#pragma once
// A measured replacement of Gouffé's closed form for cavities of every depth.
//
// Gouffé spreads the light evenly over the walls after the first reflection; in a deep
// cavity it stays near the bottom and escapes less, so the closed form is too bright (up to
// 0.27). Under diffuse light the first reflections crowd near the rim instead, and a deep
// cavity is brighter than a beam along its axis makes it. A table holds, per shape, the Monte
// Carlo reference rho(rho0, L/R) under one light (a beam along the axis, or a uniform sky) on
// a regular grid of log(L/R) and rho0, measured once offline (`impasto cracks table`), made
// non-increasing in depth. Two tables ship, one per light; a scene lit partly by the sky
// blends their differences by the sky's share. The corrected model adds to the closed form the
// bilinearly interpolated difference d = rho_table - rho_Gouffe (so it is exact wherever
// Gouffé is, as for the sphere, between the nodes too). Outside the grid it keeps both
// limits: shallower, d fades linearly in L/R to 0 at L = 0 (rho -> rho0); deeper, d decays
// as the closed form does, d_last rho_Gouffe(L/R) / rho_Gouffe(last L/R), so rho -> 0 as
// L -> inf. The result is clamped to [0, rho0].
#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/cracks/cavity.hpp"
#include "impasto/cracks/cavity_model.hpp"
#include "impasto/cracks/gouffe.hpp"
#include "impasto/util/progress.hpp"

namespace impasto::cracks {

// The light a table was measured under: a beam zenith_deg from the cavity's axis (tilted
// across a groove; 0 is Gouffé's and Kirchhoff's setting), or a uniform sky over the opening
// (cosine-weighted over the hemisphere).
struct CavityLight {
  bool diffuse = false;
  double zenith_deg = 0.0;  // the beam's; 0 .. 89

  static CavityLight beam(double zenith_deg) { return {false, zenith_deg}; }
  static CavityLight sky() { return {true, 0.0}; }
  bool operator==(const CavityLight&) const = default;
};
std::string to_string(const CavityLight& light);        // "beam:30", "diffuse"
CavityLight parse_cavity_light(std::string_view text);  // throws std::runtime_error

// The grid: L/R = ratio_min * 10^(i / ratios_per_decade), i < ratio_count;
// rho0 = j / (rho0_count - 1), j < rho0_count.
struct CavityTableGrid {
  double ratio_min = 0.05;
  int ratios_per_decade = 4;
  int ratio_count = 13;  // 0.05 .. 50
  int rho0_count = 41;   // steps of 0.025

  bool operator==(const CavityTableGrid&) const = default;
};

class CavityTable {
 public:
  // Measures the table with the Monte Carlo reference (paths per shape and L/R); progress
  // hears of each (shape, L/R) traced.
  static CavityTable measure(const CavityTableGrid& grid, CavityLight light, std::uint64_t paths,
                             std::uint64_t seed, const util::ProgressCallback& progress = {});
  // Reads a table written by write_csv; throws std::runtime_error naming the file and line.
  static CavityTable read_csv(const std::filesystem::path& path);
  void write_csv(std::ostream& out) const;

  const CavityTableGrid& grid() const { return grid_; }
  const CavityLight& light() const { return light_; }
  double ratio(int ratio_index) const;  // L/R of a grid row
  double rho0(int rho0_index) const;    // rho0 of a grid column
  // The reference's apparent reflectance at a grid point.
  float reflectance_at(CavityShape shape, int ratio_index, int rho0_index) const {
    return rho_[index(shape, ratio_index, rho0_index)];
  }
  // All values, laid out [shape][L/R][rho0] (rho0 fastest).
  const std::vector<float>& values() const { return rho_; }
  // The differences d = rho_table - rho_Gouffe, same layout: what the GPU uploads as a
  // texture of rho0_count x (6 ratio_count).
  const std::vector<float>& differences() const { return difference_; }

  // The corrected apparent reflectance for any L/R >= 0 and rho0 in [0, 1]; `vf` are the
  // cavity's own view factors (used beyond the grid's deepest row).
  double reflectance(CavityShape shape, double depth_over_half_width, const ViewFactors& vf,
                     double rho0) const {
    return reflectance_at(shape, ratio_coordinate(depth_over_half_width), vf, rho0);
  }
  // The same in two steps, so that a cell computes its L/R coordinate once for all
  // wavelengths: u = grid index of L/R (fractional); u in [-1, 0) below the grid (linear in
  // L/R, -1 at L = 0), u > ratio_count - 1 beyond it.
  double ratio_coordinate(double depth_over_half_width) const;
  double reflectance_at(CavityShape shape, double u, const ViewFactors& vf, double rho0) const {
    return clamp_to_walls(apparent_reflectance(rho0, vf) + difference_at(shape, u, rho0, vf), rho0);
  }
  // What the corrected model adds to the closed form at (u, rho0): d bilinear inside the grid,
  // fading to 0 at L = 0 below it, decaying as the closed form does beyond it.
  double difference_at(CavityShape shape, double u, double rho0, const ViewFactors& vf) const;
  // A reflectance kept within what walls of reflectance rho0 can give: [0, rho0].
  static double clamp_to_walls(double rho, double rho0);

 private:
  std::size_t index(CavityShape shape, int ratio_index, int rho0_index) const {
    return (static_cast<std::size_t>(shape) * static_cast<std::size_t>(grid_.ratio_count) +
            static_cast<std::size_t>(ratio_index)) *
               static_cast<std::size_t>(grid_.rho0_count) +
           static_cast<std::size_t>(rho0_index);
  }
  void compute_differences();
  CavityTableGrid grid_;
  CavityLight light_;
  std::vector<float> rho_;
  std::vector<float> difference_;
};

// CavityTable::difference_at for any table of differences laid out as CavityTable's on grid g
// (a blend of several tables, cavity_correction.hpp).
double interpolate_difference(const CavityTableGrid& g, std::span<const float> differences,
                              CavityShape shape, double u, double rho0, const ViewFactors& vf);

// The tables shipped in data/cracks/, read once (thread-safe), all on the same grid: beams
// at the zenith angles kShippedBeamZenithsDeg (cavity_table_beam_Z.csv) and the sky
// (cavity_table_diffuse.csv).
inline constexpr std::array<double, 7> kShippedBeamZenithsDeg{0, 15, 30, 45, 60, 75, 85};
const CavityTable& shipped_beam_table(int zenith_index);
const CavityTable& shipped_sky_table();
// The axial beam's table (zenith 0).
inline const CavityTable& shipped_cavity_table() {
  return shipped_beam_table(0);
}

}  // namespace impasto::cracks
