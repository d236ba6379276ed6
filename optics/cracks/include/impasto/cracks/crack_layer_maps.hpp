#pragma once
// Crack maps and paintings: the painting stores its cracks as plain records
// (paintcore::CrackLayer, saved in the .impasto file); the crack tools edit a CrackMap. These
// convert between the two and build the dry paint film the craquelure generator cracks.
#include <vector>

#include "impasto/cracks/crack_map.hpp"
#include "impasto/cracks/craquelure.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::cracks {

// The painting's cracks as a map of the canvas's size and cell (an empty map when uncracked).
CrackMap crack_map_of(const paintcore::Painting& painting);
// Replaces the painting's cracks by `map`, which must have the canvas's size and cell size.
// Throws std::runtime_error otherwise, or for a crack exposing a dry layer that does not exist.
void set_painting_cracks(paintcore::Painting& painting, const CrackMap& map);

// The records <-> cells conversion itself (same 64x64 tiles, same cell order).
paintcore::CrackLayer to_crack_layer(const CrackMap& map);
CrackMap to_crack_map(const paintcore::CrackLayer& layer, int width_cells, int height_cells,
                      double cell_mm);

// The thickness (mm) of each dry layer of the painting, per cell of the whole canvas
// (row-major), bottom layer first: the film generate_craquelure cracks. PaintFilm holds spans
// into these vectors.
struct DryFilm {
  std::vector<std::vector<float>> layer_thickness_mm;
  PaintFilm film() const;
};
DryFilm dry_film_of(const paintcore::Painting& painting);

// The crack tools applied to a painting's own crack map:
// craquelure of its dry layers (throws std::runtime_error naming the painting's lack of dry
// paint when it has none), and the crack brush along a polyline (mm on the canvas).
void crack_painting(paintcore::Painting& painting, const CraquelureSettings& settings);
void stamp_crack(paintcore::Painting& painting, const CrackStroke& stroke);

}  // namespace impasto::cracks
