#pragma once
// A pigment's colours as a painter checks them (docs/pigments.md): the masstone, tints with
// white and glazes over white and black, each as reflectance, XYZ, L*a*b* under a light and
// sRGB (Bradford-adapted from the light's white to D65). Kubelka–Munk throughout: opaque
// layers by R∞ of the concentration-weighted K and S, glazes as a finite layer on a ground;
// the swatches seen through the paint's surface as an instrument that includes it reads
// them (data::Saunderson: the renderer's flat layer under a uniform sky).
#include <array>
#include <string>
#include <vector>

#include "impasto/data/colorimetry.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"

namespace impasto::render {

struct SwatchColour {
  std::string label;  // "masstone", "tint 1:4", "glaze over white"
  data::Spectrum reflectance;
  data::Xyz xyz;               // Y = 100 for the light's white
  data::Lab lab;               // relative to the light's white
  std::array<double, 3> srgb;  // encoded, clamped to [0, 1]
};

// Glazes: a layer of thickness X in the database's units (K·X and S·X; S of the reference
// white = 1), thin enough to show the ground through most pigments. The grounds: white
// R = 0.9 and black R = 0.04 at every wavelength, as measured (through the paint's surface).
inline constexpr double kGlazeThickness = 0.5;
inline constexpr double kGlazeWhiteGround = 0.9, kGlazeBlackGround = 0.04;

// R∞ of `parts` of the pigment with `white_parts` of white (0: the masstone), on the
// pigment's grid.
data::Spectrum tint_reflectance(const data::Pigment& pigment, const data::Pigment& white,
                                double white_parts);
// A layer of thickness X (see kGlazeThickness) over a ground of reflectance `ground`.
data::Spectrum glaze_reflectance(const data::Pigment& pigment, double thickness, double ground);
SwatchColour describe_colour(std::string label, data::Spectrum reflectance,
                             const data::Spectrum& light);
// A reflectance inside the paint (tint_reflectance, glaze_reflectance) as measured through
// its surface: data::Saunderson's k1 + body.
data::Spectrum seen_through_surface(data::Spectrum inside);
// Masstone, tints 1:1, 1:4, 1:9, glazes over white and black, seen through the surface.
std::vector<SwatchColour> standard_swatches(const data::Pigment& pigment,
                                            const data::Pigment& white,
                                            const data::Spectrum& light);

}  // namespace impasto::render
