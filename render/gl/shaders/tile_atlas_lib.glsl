// A canvas cell's texel in a TileAtlas (render_gl/tile_atlas.hpp): its tile's place from the
// table, then the cell within the place. Needs TILE_SIZE (paintcore::kTileSize).

uniform sampler2D tile_places;  // per canvas tile: its place + 1, 0 where it has none
uniform int atlas_columns;      // places a row of the atlas

// The atlas texel of `cell` (inside the canvas), or ivec2(-1) where its tile has no place.
ivec2 atlas_texel(ivec2 cell) {
  int place = int(texelFetch(tile_places, cell / TILE_SIZE, 0).r) - 1;
  if (place < 0) return ivec2(-1);
  return ivec2(place % atlas_columns, place / atlas_columns) * TILE_SIZE + cell % TILE_SIZE;
}
