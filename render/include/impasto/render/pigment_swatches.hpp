#pragma once
// A pigment's colours as a painter checks them (docs/pigments.md): the masstone, tints with
// white and glazes over white and black, each as reflectance, XYZ, L*a*b* under a light and
// sRGB (Bradford-adapted from the light's white to D65).
//
// One colour path: a swatch is what the renderer draws for the same flat layer under a
// uniform sky. K and S are sampled at the sampling's wavelengths as SpectralPalette samples
// them (never the reflectance), the layer is the renderer's Kubelka–Munk (km::layer,
// km::composite, R∞), it is seen through the paint's surface as an instrument that includes
// it reads it (data::Saunderson: k1 + body), and the sampling's own weights make XYZ. By
// default the sampling is the renderer's reference, every nm of its range; given the
// renderer's sampling (SpectralPalette::sampling()) a swatch is its flat layer at that node
// count (tests/render/pigment_swatches_test.cpp).
#include <array>
#include <string>
#include <vector>

#include "impasto/data/colorimetry.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

struct SwatchColour {
  std::string label;           // "masstone", "tint 1:4", "glaze over white"
  data::Spectrum reflectance;  // at the sampling's wavelengths, as measured
  data::Xyz xyz;               // Y = 100 for the light's white
  data::Lab lab;               // relative to the light's white
  std::array<double, 3> srgb;  // encoded, clamped to [0, 1]
};

// Glazes: a layer of thickness X in the database's units (K·X and S·X; S of the reference
// white = 1), thin enough to show the ground through most pigments. The grounds: white
// R = 0.9 and black R = 0.04 at every wavelength, as measured (through the paint's surface).
inline constexpr double kGlazeThickness = 0.5;
inline constexpr double kGlazeWhiteGround = 0.9, kGlazeBlackGround = 0.04;

// The sampling swatches use unless given another: the renderer's reference under `light`
// (--wavelengths full: every nm of the default range, CIE 1931 2°).
SpectralSampling swatch_sampling(const data::Spectrum& light);

// Reflectances inside the paint at the sampling's wavelengths (one value a node):
// R∞ of one part of the pigment with `white_parts` of white (0: the masstone);
std::vector<float> tint_reflectance(const data::Pigment& pigment, const data::Pigment& white,
                                    double white_parts, const SpectralSampling& sampling);
// R∞ of a mix of pigments in the given shares (any positive total);
std::vector<float> mix_reflectance(const std::vector<const data::Pigment*>& pigments,
                                   const std::vector<double>& shares,
                                   const SpectralSampling& sampling);
// a layer of thickness X (see kGlazeThickness) over a ground of reflectance `ground` (inside
// the paint: one value a node, or one for every node).
std::vector<float> glaze_reflectance(const data::Pigment& pigment, double thickness,
                                     const std::vector<float>& ground,
                                     const SpectralSampling& sampling);
// A reflectance inside the paint as measured through its surface: data::Saunderson's k1 + body.
std::vector<float> seen_through_surface(std::vector<float> inside);
// The colour of a measured reflectance (one value a node) under the sampling's light.
SwatchColour describe_colour(std::string label, const std::vector<float>& reflectance,
                             const SpectralSampling& sampling);

// Masstone, tints 1:1, 1:4, 1:9, glazes over white and black, seen through the surface, at
// the reference sampling for `light` or at `sampling`.
std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const data::Spectrum& light);
std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const SpectralSampling& sampling);

}  // namespace impasto::render
