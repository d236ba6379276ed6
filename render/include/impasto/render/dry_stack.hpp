#pragma once
// The reflectance beneath a cell's wet paint: the canvas ground with the dry layers
// composited over it, bottom first, at every wavelength node. It changes only when paint
// dries or the light changes, so renderers compute it once per such change ("bake") — the
// CPU's TileRenderer and the GPU path's texture upload share this one definition.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/util/hasher.hpp"

namespace impasto::render {

// reflectance[node] for cell `cell` (0..kTileCells-1) of a tile whose dry layers (bottom
// first, the layers without paint in the tile left out) are `layers`. Slots of the layers
// must be pigments of the palette. optical_per_mm = 1 / RenderSettings::thickness_scale_mm.
void composite_dry_stack(const SpectralPalette& palette,
                         std::span<const paintcore::DryTile* const> layers, int cell,
                         float optical_per_mm, float* reflectance);

// Which dry layers a tile's bake composites and what they hold, as one number (0 for none):
// renderers keep it per tile and bake again only when it changes (the light, pigments and
// settings they track themselves). Add the layers bottom first.
class DryStackSignature {
 public:
  void add(std::size_t layer_index, const paintcore::DryTile& layer);
  std::uint64_t value() const { return any_ ? hash_.digest() : 0; }

 private:
  // A word a step: a tile's layers are tens of KB, hashed at each upload of a stroke's tiles
  // (FNV-1a byte by byte took 0.22 ms for three layers of three pigments, this 0.04 ms).
  util::Hasher hash_;
  bool any_ = false;
};

// The dry layers of a tile that show, bottom first: those with paint in the tile, less layer
// i where hidden[i] is true (the window's layer visibility), and their signature. What the
// CPU's and the GPU's bakes composite. Throws std::runtime_error naming the layer and tile for
// a layer whose sizes disagree or that uses a slot the palette lacks.
struct VisibleDryStack {
  std::vector<const paintcore::DryTile*> layers;
  std::uint64_t signature = 0;
};
VisibleDryStack visible_dry_stack(const paintcore::Canvas& canvas, int tile_index,
                                  const SpectralPalette& palette,
                                  const std::vector<bool>& hidden = {});

}  // namespace impasto::render
