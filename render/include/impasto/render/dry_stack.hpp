#pragma once
// The reflectance beneath a cell's wet paint: the canvas ground with the dry layers
// composited over it, bottom first, at every wavelength node. It changes only when paint
// dries or the light changes, so renderers compute it once per such change ("bake") — the
// CPU's TileRenderer and the GPU path's texture upload share this one definition.
#include <span>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render {

// reflectance[node] for cell `cell` (0..kTileCells-1) of a tile whose dry layers (bottom
// first, the layers without paint in the tile left out) are `layers`. Slots of the layers
// must be pigments of the palette. optical_per_mm = 1 / RenderSettings::thickness_scale_mm.
void composite_dry_stack(const SpectralPalette& palette,
                         std::span<const paintcore::DryTile* const> layers, int cell,
                         float optical_per_mm, float* reflectance);

}  // namespace impasto::render
