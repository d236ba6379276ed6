#include "impasto/cracks/accuracy.hpp"

#include "impasto/cracks/cavity_table.hpp"
#include "impasto/cracks/close_up.hpp"
#include "impasto/cracks/gouffe.hpp"

namespace impasto::cracks {

std::vector<AccuracyRow> measure_accuracy(const AccuracyGrid& grid) {
  std::vector<AccuracyRow> rows;
  for (CavityShape shape : grid.shapes) {
    for (double ratio : grid.depth_over_half_width) {
      const CavityDims dims{ratio, 1.0};
      const ViewFactors vf = view_factors(shape, dims);
      for (int pass = 0; pass < 2; ++pass) {
        const bool normal = pass == 0;
        if ((normal && !grid.normal) || (!normal && !grid.diffuse)) continue;
        const Illumination light =
            normal ? Illumination::directional(0.0) : Illumination::diffuse();
        const EscapeHistogram h = trace_cavity(shape, dims, light, grid.monte_carlo);
        // The first-reflection F is defined for a beam; under diffuse light Gouffé's F stays.
        ViewFactors vf_first = vf;
        if (normal) vf_first.F = first_reflection_view_factor(shape, dims, 0.0);
        for (double rho0 : grid.rho0) {
          rows.push_back({shape, ratio, normal ? "normal" : "diffuse", rho0,
                          h.apparent_reflectance(rho0), h.standard_error(rho0),
                          apparent_reflectance(rho0, vf), apparent_reflectance(rho0, vf_first),
                          apparent_reflectance_first_order(rho0, vf),
                          apparent_reflectance_second_order(rho0, vf),
                          cavity_reflectance(CavityModel::Corrected, shape, dims, vf, rho0)});
        }
      }
    }
  }
  return rows;
}

}  // namespace impasto::cracks
