#pragma once
// The reflectance under the wet paint at each node: the dry layers composited bottom-up over
// the canvas ground with render::composite_paint_layer (the CPU's own per-cell code). It
// changes only when a layer dries or the light changes, so it is computed on the CPU once
// per such change ("baked") and uploaded, rather than per frame in the shader.
#include <cstdint>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/dry_stack.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render_gl {

// Node-major: out[node * kTileCells + cell] for a tile whose visible dry stack is `stack`
// (render::visible_dry_stack).
void bake_dry_reflectance(const render::VisibleDryStack& stack,
                          const render::RenderSettings& settings,
                          const render::SpectralPalette& palette, std::vector<float>& out);

// Per node, what a bake stores for a cell with no dry paint: the ground's reflectance.
std::vector<float> bare_ground_reflectance(const render::RenderSettings& settings,
                                           const render::SpectralPalette& palette);

}  // namespace impasto::render_gl
