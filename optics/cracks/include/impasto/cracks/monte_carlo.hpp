#pragma once
// Monte Carlo radiosity reference for a cavity with diffuse (Lambertian) walls.
//
// Light enters through the opening; each path is followed from wall to wall with perfect
// reflection (rho0 = 1) until it leaves through the opening, and the number n of
// reflections it took is counted. Since a path that reflects n times carries rho0^n, one
// histogram gives the apparent reflectance for every rho0 at once:
//   rho(rho0) = sum_n P(n) rho0^n,   and P(1), P(2)... are the series' terms at rho0 = 1.
// Paths draw their random numbers from a counter-based generator keyed by (seed, path,
// bounce), so results are identical for any thread count.
#include <cstdint>
#include <vector>

#include "impasto/cracks/cavity.hpp"
#include "impasto/cracks/close_up.hpp"

namespace impasto::cracks {

// How light arrives at the opening.
struct Illumination {
  enum class Kind : std::uint8_t { UniformDiffuse, Directional };
  Kind kind = Kind::UniformDiffuse;
  // Directional only: angle from the canvas normal (radians), tilted across the groove
  // (in the x-z plane); for pits the azimuth does not matter.
  double zenith_rad = 0.0;

  static Illumination diffuse() { return {}; }
  static Illumination directional(double zenith_rad) { return {Kind::Directional, zenith_rad}; }
};

struct MonteCarloSettings {
  std::uint64_t paths = 100000;
  std::uint64_t seed = 1;
  // Paths longer than this are dropped; they carry at most rho0^max_bounces.
  int max_bounces = 600;
};

// Escape statistics of one cavity under one illumination.
struct EscapeHistogram {
  std::uint64_t paths = 0;
  std::vector<std::uint64_t> escaped_after;  // [n]: paths leaving after n reflections (n >= 1)
  std::uint64_t unfinished = 0;              // paths still inside after max_bounces

  // Apparent reflectance sum_n P(n) rho0^n for walls of reflectance rho0 in [0, 1].
  double apparent_reflectance(double rho0) const;
  // Its Monte Carlo standard error.
  double standard_error(double rho0) const;
  // P(n): the fraction of paths that leave after exactly n reflections.
  double escape_probability(int n) const;
};

// Follows settings.paths light paths through the cavity (parallel, deterministic).
EscapeHistogram trace_cavity(CavityShape shape, const CavityDims& dims, const Illumination& light,
                             const MonteCarloSettings& settings);

// Monte Carlo estimates of Gouffé's F and G with their standard errors.
struct ViewFactorEstimate {
  ViewFactors value;
  ViewFactors standard_error;
};
// F: diffuse rays from the deepest element (facing +z); G: diffuse rays from points spread
// uniformly over the wall area. `samples` rays for each.
ViewFactorEstimate estimate_view_factors(CavityShape shape, const CavityDims& dims,
                                         std::uint64_t samples, std::uint64_t seed);

// Monte Carlo estimate of one wall point's view factor to the opening (diffuse rays from a
// hair above the point); returns {estimate, standard error}.
std::array<double, 2> estimate_opening_view_factor(CavityShape shape, const CavityDims& dims,
                                                   const CavityWallPoint& point,
                                                   std::uint64_t samples, std::uint64_t seed);

}  // namespace impasto::cracks
