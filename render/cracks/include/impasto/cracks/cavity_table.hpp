#pragma once
// A measured replacement of Gouffé's closed form for cavities of every depth.
//
// Gouffé spreads the light evenly over the walls after the first reflection; in a deep
// cavity it stays near the bottom and escapes less, so the closed form is too bright (up to
// 0.27). The table holds, per shape, the Monte Carlo reference rho(rho0, L/R) (a beam along
// the axis) on a regular grid of log(L/R) and rho0, measured once offline (`impasto cracks
// table`), made non-increasing in depth. The corrected model adds to the closed form the
// bilinearly interpolated difference d = rho_table - rho_Gouffe (so it is exact wherever
// Gouffé is, as for the sphere, between the nodes too). Outside the grid it keeps both
// limits: shallower, d fades linearly in L/R to 0 at L = 0 (rho -> rho0); deeper, d decays
// as the closed form does, d_last rho_Gouffe(L/R) / rho_Gouffe(last L/R), so rho -> 0 as
// L -> inf. The result is clamped to [0, rho0].
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <vector>

#include "impasto/cracks/cavity.hpp"
#include "impasto/cracks/gouffe.hpp"

namespace impasto::cracks {

// Which formula gives a cavity's apparent reflectance.
enum class CavityModel : std::uint8_t {
  Gouffe,     // the closed form alone
  Corrected,  // the measured table (the default: closer to the reference everywhere)
};

// The grid: L/R = ratio_min * 10^(i / ratios_per_decade), i < ratio_count;
// rho0 = j / (rho0_count - 1), j < rho0_count.
struct CavityTableGrid {
  double ratio_min = 0.05;
  int ratios_per_decade = 4;
  int ratio_count = 13;  // 0.05 .. 50
  int rho0_count = 41;   // steps of 0.025
};

class CavityTable {
 public:
  // Measures the table with the Monte Carlo reference (paths per shape and L/R).
  static CavityTable measure(const CavityTableGrid& grid, std::uint64_t paths, std::uint64_t seed);
  // Reads a table written by write_csv; throws std::runtime_error naming the file and line.
  static CavityTable read_csv(const std::filesystem::path& path);
  void write_csv(std::ostream& out) const;

  const CavityTableGrid& grid() const { return grid_; }
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
  double reflectance_at(CavityShape shape, double u, const ViewFactors& vf, double rho0) const;

 private:
  std::size_t index(CavityShape shape, int ratio_index, int rho0_index) const {
    return (static_cast<std::size_t>(shape) * static_cast<std::size_t>(grid_.ratio_count) +
            static_cast<std::size_t>(ratio_index)) *
               static_cast<std::size_t>(grid_.rho0_count) +
           static_cast<std::size_t>(rho0_index);
  }
  void compute_differences();
  CavityTableGrid grid_;
  std::vector<float> rho_;
  std::vector<float> difference_;
};

// The table shipped in data/cracks/cavity_table.csv, read once (thread-safe).
const CavityTable& shipped_cavity_table();

// Apparent reflectance of a cavity of the given view factors under either model.
inline double cavity_reflectance(CavityModel model, CavityShape shape, const CavityDims& dims,
                                 const ViewFactors& vf, double rho0) {
  if (model == CavityModel::Gouffe) return apparent_reflectance(rho0, vf);
  return shipped_cavity_table().reflectance(shape, dims.depth_mm / dims.half_width_mm, vf, rho0);
}

}  // namespace impasto::cracks
