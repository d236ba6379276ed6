#pragma once
// Chromatic adaptation: what a viewer adapted to the light's white sees, expressed for a
// display whose white is D65.
#include <array>
#include <string_view>

#include "impasto/util/enum_names.hpp"

namespace impasto::render {

using Matrix3 = std::array<std::array<double, 3>, 3>;
using Xyz = std::array<double, 3>;

// D65 white as OpenColorIO's display transforms expect it (Y = 1).
inline constexpr Xyz kD65WhiteXyz{0.95047, 1.0, 1.08883};

enum class ChromaticAdaptation {
  none,      // XYZ passes unchanged: a warm light looks warm on the display
  bradford,  // the light's white maps to D65 white (von Kries in the Bradford cone space)
};

// Its spellings (--adaptation), the default first.
inline constexpr util::EnumNames<ChromaticAdaptation, 2> kChromaticAdaptationNames{
    {{ChromaticAdaptation::bradford, "bradford"}, {ChromaticAdaptation::none, "none"}}};

// Parses a name of kChromaticAdaptationNames; throws std::runtime_error naming them.
ChromaticAdaptation parse_chromatic_adaptation(std::string_view text);

// The matrix taking XYZ seen under source_white to XYZ under target_white.
Matrix3 bradford_matrix(const Xyz& source_white, const Xyz& target_white);

Matrix3 identity_matrix();
// Throws std::runtime_error for a singular matrix.
Matrix3 inverse(const Matrix3& m);
Matrix3 multiply(const Matrix3& a, const Matrix3& b);
Xyz apply(const Matrix3& m, const Xyz& v);

}  // namespace impasto::render
