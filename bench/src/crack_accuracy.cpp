#include "impasto/bench/crack_accuracy.hpp"

#include <cmath>
#include <numbers>

#include "impasto/cracks/cavity_correction.hpp"
#include "impasto/cracks/close_up.hpp"
#include "impasto/cracks/gouffe.hpp"

namespace impasto::bench {

using namespace impasto::cracks;  // (this measures its parts)

std::vector<AccuracyRow> measure_crack_accuracy(const AccuracyGrid& grid) {
  std::vector<AccuracyRow> rows;
  for (CavityShape shape : grid.shapes) {
    for (double ratio : grid.depth_over_half_width) {
      const CavityDims dims{ratio, 1.0};
      const ViewFactors vf = view_factors(shape, dims);
      const bool need_diffuse = grid.diffuse || grid.scene;
      const EscapeHistogram sky =
          need_diffuse ? trace_cavity(shape, dims, Illumination::diffuse(), grid.monte_carlo)
                       : EscapeHistogram{};
      for (int pass = 0; pass < 2; ++pass) {
        const bool normal = pass == 0;
        if ((normal && !grid.normal) || (!normal && !grid.diffuse)) continue;
        const EscapeHistogram h =
            normal ? trace_cavity(shape, dims, Illumination::directional(0.0), grid.monte_carlo)
                   : sky;
        // The first-reflection F is defined for a beam; under diffuse light Gouffé's F stays.
        ViewFactors vf_first = vf;
        if (normal) vf_first.F = first_reflection_view_factor(shape, dims, 0.0);
        for (double rho0 : grid.rho0) {
          rows.push_back({shape, ratio, normal ? "normal" : "diffuse", rho0,
                          h.apparent_reflectance(rho0), h.standard_error(rho0),
                          apparent_reflectance(rho0, vf), apparent_reflectance(rho0, vf_first),
                          apparent_reflectance_first_order(rho0, vf),
                          apparent_reflectance_second_order(rho0, vf),
                          cavity_reflectance(CavityModel::Corrected, shape, dims, vf, rho0,
                                             {0.0, normal ? 0.0 : 1.0, false})});
        }
      }
      if (grid.scene) {
        // Light adds up: the scene's reflectance is the sun's and the sky's, weighted by
        // their shares of the irradiance; the two runs are independent.
        const double s = grid.scene_sky_share;
        const EscapeHistogram sun = trace_cavity(
            shape, dims,
            Illumination::directional(grid.scene_zenith_deg * std::numbers::pi / 180.0),
            grid.monte_carlo);
        for (double rho0 : grid.rho0) {
          const double reference =
              (1.0 - s) * sun.apparent_reflectance(rho0) + s * sky.apparent_reflectance(rho0);
          const double error =
              std::hypot((1.0 - s) * sun.standard_error(rho0), s * sky.standard_error(rho0));
          rows.push_back({shape, ratio, "scene", rho0, reference, error,
                          apparent_reflectance(rho0, vf), apparent_reflectance(rho0, vf),
                          apparent_reflectance_first_order(rho0, vf),
                          apparent_reflectance_second_order(rho0, vf),
                          cavity_reflectance(CavityModel::Corrected, shape, dims, vf, rho0,
                                             {grid.scene_zenith_deg, s, false})});
        }
      }
    }
  }
  return rows;
}

}  // namespace impasto::bench
