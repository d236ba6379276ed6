#pragma once
// IMPASTO_SIMD_CLONES and the value-returning min/max: one copy, in util/.
#include "impasto/util/simd_clones.hpp"

namespace impasto::paintcore {

using util::greater;
using util::lesser;

}  // namespace impasto::paintcore
