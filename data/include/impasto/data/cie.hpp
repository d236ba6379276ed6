#pragma once
// CIE tables shipped in data_dir()/spectra (converted from Debian's colord-data).
#include <string>
#include <string_view>
#include <vector>

#include "impasto/data/spectrum.hpp"

namespace impasto::data {

// CIE 1931 2° standard observer, 360..830 nm every 5 nm; ȳ = 1 at 555 nm. Loaded once.
const ColorMatchingFunctions& cie1931_2deg();

// A CIE standard illuminant's relative spectral power distribution ("A", "D50", "D65",
// "F2", "F7", "F11", ...; case-insensitive). Throws std::runtime_error listing the names.
Spectrum cie_illuminant(std::string_view name);

// The illuminants cie_illuminant() knows, in natural order (A, B, ..., F2, F3, ..., F12).
std::vector<std::string> illuminant_names();

}  // namespace impasto::data
