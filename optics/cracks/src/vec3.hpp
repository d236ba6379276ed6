#pragma once
// The cavity ray tracer's 3-vector (mm): util's, the same type as the public Vec3d.
#include <impasto/util/vec3.hpp>

namespace impasto::cracks::detail {

using Vec3 = util::Vec3<double>;

}  // namespace impasto::cracks::detail
