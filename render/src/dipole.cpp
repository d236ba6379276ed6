#include "impasto/render/dipole.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace impasto::render::dipole {

Medium from_kubelka_munk(double absorption, double scattering, double thickness_scale_mm,
                         double eta) {
  const double per_mm = 1.0 / thickness_scale_mm;
  Medium m;
  m.absorption_per_mm = 0.5 * absorption * per_mm;
  m.reduced_scattering_per_mm = (4.0 / 3.0) * (scattering + 0.125 * absorption) * per_mm;
  m.eta = eta;
  return m;
}

double diffuse_fresnel_reflectance(double eta) {
  return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

double effective_extinction_per_mm(const Medium& m) {
  const double extinction = m.absorption_per_mm + m.reduced_scattering_per_mm;
  return std::sqrt(3.0 * m.absorption_per_mm * extinction);
}

double diffusion_length_mm(const Medium& m) {
  const double sigma_tr = effective_extinction_per_mm(m);
  return sigma_tr > 0.0 ? 1.0 / sigma_tr : std::numeric_limits<double>::infinity();
}

double reduced_albedo(const Medium& m) {
  const double extinction = m.absorption_per_mm + m.reduced_scattering_per_mm;
  return extinction > 0.0 ? m.reduced_scattering_per_mm / extinction : 0.0;
}

double profile(const Medium& m, double r_mm) {
  const double extinction = m.absorption_per_mm + m.reduced_scattering_per_mm;
  if (!(extinction > 0.0)) return 0.0;
  const double fdr = diffuse_fresnel_reflectance(m.eta);
  const double a = (1.0 + fdr) / (1.0 - fdr);
  const double sigma_tr = effective_extinction_per_mm(m);
  const double z_r = 1.0 / extinction;
  const double z_v = z_r * (1.0 + 4.0 * a / 3.0);
  const double d_r = std::sqrt(r_mm * r_mm + z_r * z_r);
  const double d_v = std::sqrt(r_mm * r_mm + z_v * z_v);
  const double real = z_r * (sigma_tr * d_r + 1.0) * std::exp(-sigma_tr * d_r) / (d_r * d_r * d_r);
  const double image = z_v * (sigma_tr * d_v + 1.0) * std::exp(-sigma_tr * d_v) / (d_v * d_v * d_v);
  return reduced_albedo(m) / (4.0 * std::numbers::pi) * (real + image);
}

double total_reflectance(const Medium& m) {
  const double albedo = reduced_albedo(m);
  const double fdr = diffuse_fresnel_reflectance(m.eta);
  const double a = (1.0 + fdr) / (1.0 - fdr);
  const double root = std::sqrt(3.0 * (1.0 - albedo));
  return 0.5 * albedo * (1.0 + std::exp(-(4.0 / 3.0) * a * root)) * std::exp(-root);
}

}  // namespace impasto::render::dipole
