#pragma once
// Which formula gives a cavity's apparent reflectance: the one choice the cracks library, the
// renderer's settings (render::CrackModel) and the command line share.
#include <cstdint>

#include "impasto/util/enum_names.hpp"

namespace impasto::cracks {

enum class CavityModel : std::uint8_t {
  Gouffe,     // the closed form alone: fast, too bright in deep narrow cavities (up to 0.27)
  Corrected,  // the measured table (the default: closer to the reference everywhere)
};

// The spellings of `impasto render --crack-model`, the default first.
inline constexpr util::EnumNames<CavityModel, 2> kCavityModelNames{
    {{CavityModel::Corrected, "corrected"}, {CavityModel::Gouffe, "gouffe"}}};

}  // namespace impasto::cracks
