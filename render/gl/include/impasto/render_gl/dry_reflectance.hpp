#pragma once
// The reflectance under the wet paint at each node: the dry layers composited bottom-up over
// the canvas ground with render::composite_paint_layer (the CPU's own per-cell code). It
// changes only when a layer dries or the light changes, so it is computed on the CPU once
// per such change ("baked") and uploaded, rather than per frame in the shader.
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render_gl {

// Node-major: out[node * kTileCells + cell] for the tile `tile_index` of `canvas`. Dry
// layer i is left out where hidden[i] is true (the window's layer visibility).
void bake_dry_reflectance(const paintcore::Canvas& canvas, int tile_index,
                          const render::RenderSettings& settings,
                          const render::SpectralPalette& palette, std::vector<float>& out,
                          const std::vector<bool>& hidden = {});

}  // namespace impasto::render_gl
