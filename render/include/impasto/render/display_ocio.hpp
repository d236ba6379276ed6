#pragma once
// The OpenColorIO transform (XYZ D65 to display RGB) of each display encoding: the one
// definition shared by the CPU DisplayTransform and the GPU shader of render/gl.
// Including this needs OpenColorIO's headers on the include path.
#include <OpenColorIO/OpenColorIO.h>

#include "impasto/render/display.hpp"

namespace impasto::render {

OCIO_NAMESPACE::TransformRcPtr display_ocio_transform(DisplayEncoding encoding);

}  // namespace impasto::render
