// Painting::set_cracks: the crack layer, checked and swapped in, its changes marked dirty.
#include <algorithm>

#include "painting_impl.hpp"

namespace impasto::paintcore {

void Painting::set_cracks(CrackLayer cracks) {
  Canvas& canvas = impl_->canvas;
  validate_cracks(cracks, canvas.width_cells(), canvas.height_cells(), canvas.dry_layers().size());
  for (int index = 0; index < cracks.tile_extent(); ++index) {
    const CrackTile* tile = cracks.tile(index);
    if (tile != nullptr && std::none_of(tile->cells.begin(), tile->cells.end(),
                                        [](const CrackRecord& r) { return r.has_crack(); })) {
      cracks.erase_tile(index);
    }
  }
  const CrackLayer& old = canvas.cracks();
  const int extent = std::max(old.tile_extent(), cracks.tile_extent());
  for (int index = 0; index < extent; ++index) {
    const CrackTile* a = old.tile(index);
    const CrackTile* b = cracks.tile(index);
    if ((a == nullptr) != (b == nullptr) || (a != nullptr && a->cells != b->cells)) {
      canvas.mark_dirty(index);
    }
  }
  canvas.cracks() = std::move(cracks);
}

}  // namespace impasto::paintcore
