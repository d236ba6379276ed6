#include "impasto/cracks/cavity_look.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "impasto/cracks/gouffe.hpp"

namespace impasto::cracks {

double crack_coverage(const CrackCell& cell, double cell_mm) {
  if (!cell.has_crack()) return 0.0;
  const double R = cell.half_width_mm;
  const double c =
      is_groove(cell.shape) ? 2.0 * R / cell_mm : std::numbers::pi * R * R / (cell_mm * cell_mm);
  return std::clamp(c, 0.0, 1.0);
}

void crack_cell_reflectance(const CrackCell& cell, double cell_mm, std::span<const float> surface,
                            std::span<const float> wall, std::span<float> out,
                            const CavityCorrection* correction) {
  if (surface.size() != out.size() || wall.size() != out.size()) {
    throw std::invalid_argument("crack_cell_reflectance: spectra of different lengths");
  }
  if (!cell.has_crack()) {
    if (out.data() != surface.data()) std::copy(surface.begin(), surface.end(), out.begin());
    return;
  }
  const ViewFactors vf = view_factors(cell.shape, cell.dims());
  const double c = crack_coverage(cell, cell_mm);
  const double u =
      correction != nullptr
          ? correction->ratio_coordinate(static_cast<double>(cell.depth_mm) / cell.half_width_mm)
          : 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double rho0 = std::clamp(static_cast<double>(wall[i]), 0.0, 1.0);
    const double rho = correction != nullptr ? correction->reflectance_at(cell.shape, u, vf, rho0)
                                             : apparent_reflectance(rho0, vf);
    out[i] = static_cast<float>((1.0 - c) * surface[i] + c * rho);
  }
}

void crack_cell_reflectance(const CrackCell& cell, double cell_mm, std::span<const float> surface,
                            std::span<const float> wall, std::span<float> out, CavityModel model) {
  const auto correction = model == CavityModel::Corrected ? cavity_correction({}) : nullptr;
  crack_cell_reflectance(cell, cell_mm, surface, wall, out, correction.get());
}

}  // namespace impasto::cracks
