#pragma once
// Canvas tiles' data on the GPU, only for the tiles that hold some: an array texture of
// tile-sized places, filled row after row and grown as tiles arrive, and a table (one texel a
// canvas tile) of where each tile sits. A bare tile has no place and costs no memory; the
// shader stands in what it would hold (tile_atlas_lib.glsl). Full-canvas float textures of a
// 4096x3072 canvas were 200 MB a layer, all cleared before the window's first frame.
#include <cstddef>
#include <vector>

#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class TileAtlas {
 public:
  TileAtlas() = default;
  // For a canvas of tiles_x x tiles_y tiles, `layers` RGBA32F layers a place. Allocates only
  // the table; the places come with the tiles.
  TileAtlas(int tiles_x, int tiles_y, int layers);

  bool placed(int tile_index) const;
  // Gives the tile a place if it has none; a full texture grows (twice the rows), keeping
  // what it holds. Throws std::runtime_error when the GPU cannot hold a texture that large.
  void place(int tile_index);
  // Grows the texture now to hold `places` (at most every tile): a growth allocates
  // and copies the whole texture (40-140 ms on llvmpipe for 64-256 places of 4 layers), so
  // callers make room ahead of need while nothing waits.
  void reserve(int places);
  // Writes `layer` of the tile's place from w x h texels (4 floats each) whose rows are
  // row_stride texels apart. The tile must be placed (std::logic_error otherwise).
  void upload(int tile_index, int w, int h, int layer, const float* texels, int row_stride);

  // The atlas to `atlas_unit`, the table to `table_unit`.
  void bind(int atlas_unit, int table_unit) const;
  int columns() const { return columns_; }  // places a row, as the shader counts them
  int layers() const { return layers_; }
  int places() const { return count_; }
  int capacity() const { return rows_ * columns_; }
  std::size_t bytes() const;  // GPU memory of the atlas and the table

 private:
  void grow_to(int rows);

  int tiles_x_ = 0, tiles_y_ = 0, layers_ = 0;
  int columns_ = 1;            // places a row
  int max_rows_ = 1;           // rows enough for every tile (or what the GPU allows)
  int rows_ = 0;               // rows allocated
  int count_ = 0;              // places given
  std::vector<int> place_of_;  // per tile: its place, -1 where none
  Texture atlas_;              // columns_ x rows_ places of kTileSize^2 texels, layers_ deep
  Texture table_;              // per tile: its place + 1 (R32F, exact to 2^24), 0: none
};

}  // namespace impasto::render_gl
