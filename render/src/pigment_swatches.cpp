#include "impasto/render/pigment_swatches.hpp"

#include <cmath>
#include <stdexcept>

#include "impasto/data/cie.hpp"
#include "impasto/data/kubelka_munk.hpp"
#include "impasto/render/chromatic_adaptation.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/kubelka_munk_cell.hpp"

namespace impasto::render {

SpectralSampling swatch_sampling(const data::Spectrum& light) {
  return make_spectral_sampling(light, data::cie1931_2deg(), 0);
}

std::vector<float> mix_reflectance(const std::vector<const data::Pigment*>& pigments,
                                   const std::vector<double>& shares,
                                   const SpectralSampling& sampling) {
  if (pigments.empty() || pigments.size() != shares.size())
    throw std::invalid_argument("mix_reflectance: one share for each pigment");
  double total = 0.0;
  for (const double share : shares) total += share;
  if (!(total > 0.0) || !std::isfinite(total))
    throw std::invalid_argument("mix_reflectance: the shares must add up to a positive number");
  // K and S at the nodes as SpectralPalette samples them, then Eq. 5 as the renderer adds them.
  std::vector<float> absorption(static_cast<std::size_t>(sampling.size()), 0.0f);
  std::vector<float> scattering(absorption.size(), 0.0f);
  for (std::size_t p = 0; p < pigments.size(); ++p) {
    const std::vector<float> k = sample_at_nodes(pigments[p]->K, sampling);
    const std::vector<float> s = sample_at_nodes(pigments[p]->S, sampling);
    const auto concentration = static_cast<float>(shares[p] / total);
    for (std::size_t i = 0; i < k.size(); ++i)
      km::accumulate_pigment(concentration, k[i], s[i], absorption[i], scattering[i]);
  }
  std::vector<float> r(absorption.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = km::reflectance_infinite(absorption[i], scattering[i]);
  return r;
}

std::vector<float> tint_reflectance(const data::Pigment& pigment, const data::Pigment& white,
                                    double white_parts, const SpectralSampling& sampling) {
  if (white_parts <= 0.0) return mix_reflectance({&pigment}, {1.0}, sampling);
  return mix_reflectance({&pigment, &white}, {1.0, white_parts}, sampling);
}

std::vector<float> glaze_reflectance(const data::Pigment& pigment, double thickness,
                                     const std::vector<float>& ground,
                                     const SpectralSampling& sampling) {
  const auto n = static_cast<std::size_t>(sampling.size());
  if (ground.size() != n && ground.size() != 1)
    throw std::invalid_argument("glaze_reflectance: one ground value, or one a node");
  const std::vector<float> k = sample_at_nodes(pigment.K, sampling);
  const std::vector<float> s = sample_at_nodes(pigment.S, sampling);
  std::vector<float> r(n);
  for (std::size_t i = 0; i < n; ++i) {
    const km::LayerRT layer = km::layer(k[i], s[i], static_cast<float>(thickness));
    r[i] = km::composite(layer, ground.size() == 1 ? ground[0] : ground[i]);
  }
  return r;
}

std::vector<float> seen_through_surface(std::vector<float> inside) {
  const data::Saunderson surface;
  for (float& r : inside) r = static_cast<float>(surface.to_measured(r));
  return inside;
}

SwatchColour describe_colour(std::string label, const std::vector<float>& reflectance,
                             const SpectralSampling& sampling) {
  if (reflectance.size() != static_cast<std::size_t>(sampling.size()))
    throw std::invalid_argument("describe_colour: one reflectance a node");
  SwatchColour c{std::move(label), {"R", {}, {}}, {}, {}, {}};
  for (std::size_t i = 0; i < reflectance.size(); ++i) {
    c.reflectance.wavelengths_nm.push_back(sampling.wavelengths_nm[i]);
    c.reflectance.values.push_back(reflectance[i]);
  }
  const std::array<double, 3> xyz = reflectance_to_xyz(sampling, reflectance.data());
  c.xyz = {100 * xyz[0], 100 * xyz[1], 100 * xyz[2]};
  const data::Xyz white{100 * sampling.white_xyz[0], 100 * sampling.white_xyz[1],
                        100 * sampling.white_xyz[2]};
  c.lab = data::xyz_to_lab(c.xyz, white);
  const Matrix3 adapt = bradford_matrix(sampling.white_xyz, kD65WhiteXyz);
  const Xyz d65 = apply(adapt, {xyz[0], xyz[1], xyz[2]});
  const auto m = xyz_to_linear_srgb();
  for (std::size_t i = 0; i < 3; ++i)
    c.srgb[i] = srgb_encoded(m[3 * i] * d65[0] + m[3 * i + 1] * d65[1] + m[3 * i + 2] * d65[2]);
  return c;
}

std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const data::Spectrum& light) {
  return standard_swatches(pigment, white, swatch_sampling(light));
}

std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const SpectralSampling& sampling) {
  const auto swatch = [&](std::string label, std::vector<float> inside) {
    return describe_colour(std::move(label), seen_through_surface(std::move(inside)), sampling);
  };
  std::vector<SwatchColour> out;
  out.push_back(swatch("masstone", tint_reflectance(pigment, white, 0, sampling)));
  for (int parts : {1, 4, 9}) {
    out.push_back(swatch("tint 1:" + std::to_string(parts),
                         tint_reflectance(pigment, white, parts, sampling)));
  }
  // The grounds as measured, under the glaze as the paint sees them from inside.
  const data::Saunderson surface;
  for (const auto& [label, ground] : {std::pair{"glaze over white", kGlazeWhiteGround},
                                      std::pair{"glaze over black", kGlazeBlackGround}}) {
    const std::vector<float> inside{static_cast<float>(surface.to_internal(ground))};
    out.push_back(swatch(label, glaze_reflectance(pigment, kGlazeThickness, inside, sampling)));
  }
  return out;
}

}  // namespace impasto::render
