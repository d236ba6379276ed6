#pragma once
// Light sources as relative spectral power distributions (nm → relative power).
#include <string_view>
#include <vector>

#include "impasto/data/cie.hpp"
#include "impasto/data/spectrum.hpp"

namespace impasto::data {

// Planck's law at `kelvin` (>= 100 K) sampled on grid_nm, normalised to 1 at 560 nm.
// Throws std::runtime_error for a colder or non-finite temperature or a bad wavelength.
Spectrum blackbody(double kelvin, const std::vector<double>& grid_nm);

// A light named by the user: a CIE illuminant ("D65", "A", ...), "blackbody:KELVIN"
// (sampled 300..830 nm every 1 nm), or the path of a spectral CSV with one column of
// quantity spectral_power. Throws std::runtime_error saying what was expected.
Spectrum light_from_spec(std::string_view spec);

}  // namespace impasto::data
