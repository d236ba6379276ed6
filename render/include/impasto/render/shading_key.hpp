#pragma once
// What in the render settings changes a cell's shading factors (the light's direction, the
// ambient share, the materials and gloss, the relief's shadows and occlusion), as numbers to
// compare: the CPU renderer's relight (TileRenderer) reuses its cached factors, and the
// window's cached view (render_gl::ShadedViewCache) its image, only while it is unchanged.
// A setting that changes the shading goes here, once, so that neither cache keeps a stale one
// (tests/render/shading_key_test.cpp changes each).
#include <vector>

#include "impasto/render/render_settings.hpp"

namespace impasto::render {

std::vector<double> shading_settings_key(const RenderSettings& settings);

}  // namespace impasto::render
