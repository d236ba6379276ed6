#include "impasto/render/pigment_swatches.hpp"

#include <algorithm>
#include <cmath>

#include "impasto/data/kubelka_munk.hpp"
#include "impasto/render/chromatic_adaptation.hpp"
#include "impasto/render/display.hpp"

namespace impasto::render {
data::Spectrum tint_reflectance(const data::Pigment& pigment, const data::Pigment& white,
                                double white_parts) {
  data::Spectrum out{"R", pigment.K.wavelengths_nm, {}};
  const double share = 1.0 / (1.0 + white_parts);
  for (double nm : out.wavelengths_nm) {
    const double k = share * pigment.K.at(nm) + (1 - share) * white.K.at(nm);
    const double s = share * pigment.S.at(nm) + (1 - share) * white.S.at(nm);
    out.values.push_back(data::reflectance_infinite(k, s));
  }
  return out;
}

data::Spectrum glaze_reflectance(const data::Pigment& pigment, double thickness, double ground) {
  data::Spectrum out{"R", pigment.K.wavelengths_nm, {}};
  for (double nm : out.wavelengths_nm) {
    const double k = pigment.K.at(nm), s = pigment.S.at(nm);
    double r;
    if (s * thickness < 1e-9) {
      r = ground * std::exp(-2 * k * thickness);  // a clear layer: absorption both ways
    } else {
      // Kubelka (1954): a = (S + K)/S, b = sqrt(a² − 1).
      const double a = (s + k) / s, b = std::sqrt(a * a - 1);
      const double coth = 1 / std::tanh(std::max(b * s * thickness, 1e-12));
      r = (1 - ground * (a - b * coth)) / (a - ground + b * coth);
    }
    out.values.push_back(std::clamp(r, 0.0, 1.0));
  }
  return out;
}

SwatchColour describe_colour(std::string label, data::Spectrum reflectance,
                             const data::Spectrum& light) {
  SwatchColour c{std::move(label), std::move(reflectance), {}, {}, {}};
  c.xyz = data::reflectance_to_xyz(c.reflectance, light);
  const data::Xyz white = data::white_point(light);
  c.lab = data::xyz_to_lab(c.xyz, white);
  const Matrix3 adapt =
      bradford_matrix({white.X / 100, white.Y / 100, white.Z / 100}, kD65WhiteXyz);
  const Xyz d65 = apply(adapt, {c.xyz.X / 100, c.xyz.Y / 100, c.xyz.Z / 100});
  const auto m = xyz_to_linear_srgb();
  for (int i = 0; i < 3; ++i) {
    c.srgb[static_cast<std::size_t>(i)] =
        srgb_encoded(m[3 * i] * d65[0] + m[3 * i + 1] * d65[1] + m[3 * i + 2] * d65[2]);
  }
  return c;
}

data::Spectrum seen_through_surface(data::Spectrum inside) {
  const data::Saunderson surface;
  for (double& r : inside.values) r = surface.to_measured(r);
  return inside;
}

std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const data::Spectrum& light) {
  const data::Saunderson surface;
  const auto swatch = [&](std::string label, data::Spectrum inside) {
    return describe_colour(std::move(label), seen_through_surface(std::move(inside)), light);
  };
  std::vector<SwatchColour> out;
  out.push_back(swatch("masstone", tint_reflectance(pigment, white, 0)));
  for (int parts : {1, 4, 9}) {
    out.push_back(
        swatch("tint 1:" + std::to_string(parts), tint_reflectance(pigment, white, parts)));
  }
  // The grounds as measured, under the glaze as the paint sees them from inside.
  out.push_back(
      swatch("glaze over white",
             glaze_reflectance(pigment, kGlazeThickness, surface.to_internal(kGlazeWhiteGround))));
  out.push_back(
      swatch("glaze over black",
             glaze_reflectance(pigment, kGlazeThickness, surface.to_internal(kGlazeBlackGround))));
  return out;
}

}  // namespace impasto::render
