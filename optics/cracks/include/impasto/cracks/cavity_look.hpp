#pragma once
// The renderer's hooks: what a cracked cell looks like from afar, per wavelength.
#include <span>

#include "impasto/cracks/cavity_correction.hpp"
#include "impasto/cracks/crack_map.hpp"

namespace impasto::cracks {

// Fraction of a cell's area taken by the crack's opening: a groove crossing the cell,
// min(1, 2R / cell); a pit, min(1, pi R^2 / cell^2).
double crack_coverage(const CrackCell& cell, double cell_mm);

// Far view: the cell's reflectance with its crack, per wavelength,
//   out = (1 - c) surface + c rho_cavity(wall),
// with c the coverage and rho_cavity the apparent reflectance of the cavity whose walls have
// reflectance `wall` (the exposed layer's, from the renderer): Gouffé's closed form where
// `correction` is null, else corrected for the scene's light (cavity_correction.hpp). All
// spans have
// the same length (one value per wavelength of the renderer's quadrature); out may alias
// surface. A cell without a crack copies surface. Throws std::invalid_argument on a size
// mismatch.
void crack_cell_reflectance(const CrackCell& cell, double cell_mm, std::span<const float> surface,
                            std::span<const float> wall, std::span<float> out,
                            const CavityCorrection* correction);
// The same with the model named: Corrected uses the correction for a beam along the axis.
void crack_cell_reflectance(const CrackCell& cell, double cell_mm, std::span<const float> surface,
                            std::span<const float> wall, std::span<float> out,
                            CavityModel model = CavityModel::Corrected);

}  // namespace impasto::cracks
