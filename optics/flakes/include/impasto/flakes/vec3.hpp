#pragma once
// The sparkle maths' 3-vector (util's). Canvas frame: x, y on the canvas (mm), z up out of the
// canvas towards the viewer.
#include <impasto/util/vec3.hpp>

namespace impasto::flakes {

using Vec3 = util::Vec3<double>;

}  // namespace impasto::flakes
