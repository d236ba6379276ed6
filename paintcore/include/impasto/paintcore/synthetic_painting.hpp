#pragma once
// A big painting made without painting it, for measuring the painting file's save and load
// (`impasto bench io`) and for the tests of big sparse canvases: a share of the tiles, spread
// over the canvas, hold wet paint of every slot and a dry layer of one slot, varying cell to
// cell. Deterministic: the same spec gives the same bytes.
#include <string>
#include <vector>

#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {

struct SyntheticPaintingSpec {
  int width_cells = 16384;
  int height_cells = 16384;
  double painted_share = 0.03;     // of the canvas's tiles, spread evenly over it
  std::vector<std::string> slots;  // pigment names (each tile holds them all)
  int dry_layers = 1;              // each over the same painted tiles, one slot a tile
};

// Throws std::invalid_argument when the spec is not usable (a canvas spec's error, a share
// outside [0, 1], more than kMaxPigmentSlots slots, a negative or absurd layer count).
Painting synthetic_painting(const SyntheticPaintingSpec& spec, int threads = 0);

// The bytes one wet tile takes in the file with `slots` slots, and one dry tile of one slot.
std::uint64_t painting_file_wet_tile_bytes(int slots);
std::uint64_t painting_file_dry_tile_bytes(int slots);

}  // namespace impasto::paintcore
