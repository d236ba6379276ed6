#pragma once
// CIE colorimetry: tristimulus values of reflectances under a light, L*a*b*, CIEDE2000.
#include "impasto/data/cie.hpp"
#include "impasto/data/spectrum.hpp"

namespace impasto::data {

struct Xyz {
  double X = 0, Y = 0, Z = 0;
};
struct Lab {
  double L = 0, a = 0, b = 0;
};
struct Chromaticity {
  double x = 0, y = 0;
};

// Tristimulus values of `reflectance` lit by `light`, scaled so that the perfect reflecting
// diffuser (R = 1) has Y = 100. Integrated every 1 nm over the observer's range (360–830 nm
// for CIE 1931) with linear interpolation; the reflectance is held at its end values
// outside its own range (CIE 15 practice), the light is 0 outside its range.
Xyz reflectance_to_xyz(const Spectrum& reflectance, const Spectrum& light,
                       const ColorMatchingFunctions& observer = cie1931_2deg());

// The light's white: XYZ of the perfect reflecting diffuser, Y = 100.
Xyz white_point(const Spectrum& light, const ColorMatchingFunctions& observer = cie1931_2deg());

// x = X / (X + Y + Z), y = Y / (X + Y + Z); (0, 0) for black.
Chromaticity chromaticity(const Xyz& xyz);

// CIE 1976 L*a*b* relative to `white` (both with the same Y scale).
Lab xyz_to_lab(const Xyz& xyz, const Xyz& white);

// CIEDE2000 colour difference (Sharma, Wu, Dalal 2005) with kL = kC = kH = 1.
double ciede2000(const Lab& first, const Lab& second);

// CIEDE2000 between two reflectances seen under `light`, each relative to the light's white
// (how a fit's error against a measurement is told).
double reflectance_delta_e(const Spectrum& first, const Spectrum& second, const Spectrum& light);

}  // namespace impasto::data
