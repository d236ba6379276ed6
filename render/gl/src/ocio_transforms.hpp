#pragma once
// The OpenColorIO transform of each display encoding, as render::DisplayTransform builds it
// for the CPU (render/src/display.cpp). Mirrored here because that one is private to the
// render module; the GPU image tests compare the two pixel by pixel.
#include <OpenColorIO/OpenColorIO.h>

#include "impasto/render/display.hpp"

namespace impasto::render_gl {

OCIO_NAMESPACE::TransformRcPtr display_ocio_transform(render::DisplayEncoding encoding);

}  // namespace impasto::render_gl
