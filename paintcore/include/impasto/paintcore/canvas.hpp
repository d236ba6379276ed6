#pragma once
// The canvas: a grid of cells at a DPI, stored in 64x64 tiles that exist only where paint
// has been. Per cell: the base canvas height (a procedural weave), the combined height of
// the dry layers, and ONE wet layer (paint volume and the amounts of up to 16 pigments).
//
// Units: heights and volumes per cell are millimetres of paint height (volume per cell
// area); multiply by cell_area_mm2() for mm^3. Pigment amounts are volumes too (the part of
// the paint volume that is that pigment), so concentration = amount / volume.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "impasto/paintcore/changed_cells.hpp"
#include "impasto/paintcore/crack_layer.hpp"

namespace impasto::paintcore {

inline constexpr int kTileSize = 64;                      // cells along a tile edge
inline constexpr int kTileCells = kTileSize * kTileSize;  // cells in a tile
inline constexpr int kMaxPigmentSlots = 16;               // pigment slots of a painting
inline constexpr double kMmPerInch = 25.4;                // dpi and cell sizes
inline constexpr int kMaxCanvasCells = 1 << 17;           // per side
// No cell of the canvas or the brush holds a metre of paint: a load that would put more on
// a brush cell is refused, and a painting file holding more is refused as crafted, so what
// is painted can always be saved and opened again.
inline constexpr float kMaxPaintHeightMm = 1000.0f;
static_assert(kCrackTileCells == kTileCells, "crack tiles are canvas tiles");

struct CanvasSpec {
  int width_cells = 0;
  int height_cells = 0;
  double dpi = 0.0;
  std::uint64_t weave_seed = 1;  // 0: a flat canvas (base height 0 everywhere)
  // The cell of the cloth under the canvas's top-left cell: a crop or an anchored resize
  // moves it, so the weave stays under the paint (canvas_reframe.hpp).
  std::int64_t weave_origin_x_cells = 0;
  std::int64_t weave_origin_y_cells = 0;

  double cell_mm() const { return kMmPerInch / dpi; }
  double cell_area_mm2() const { return cell_mm() * cell_mm(); }
};

// Throws std::runtime_error naming the field when the spec is not usable.
void validate(const CanvasSpec& spec);

// One 64x64 tile. Cells are row-major (local index = y * kTileSize + x); cells of an edge
// tile that lie outside the canvas stay zero. Pigments are slot-major: the amounts of slot s
// are pigment[s * kTileCells + cell]; a tile holds as many slots as the painting had when it
// was last written (missing slots read as zero).
struct Tile {
  std::array<float, kTileCells> base_height_mm{};  // the weave, cached when the tile is made
  std::array<float, kTileCells> dry_height_mm{};   // sum of all dry layers
  std::array<float, kTileCells> wet_volume_mm{};   // wet paint height
  std::vector<float> pigment_mm;                   // wet pigment amounts, slot-major
  // The surface's medium and varnish per cell (paint_surface.hpp), plane-major; empty in
  // tiles that never had either.
  std::vector<float> medium;
  std::vector<float> varnish;

  int slot_count() const { return static_cast<int>(pigment_mm.size() / kTileCells); }
  // Amounts of one slot (kTileCells values), or nullptr when the tile lacks that slot.
  const float* pigment(int slot) const {
    return slot < slot_count() ? pigment_mm.data() + static_cast<std::size_t>(slot) * kTileCells
                               : nullptr;
  }
  float* pigment(int slot) {
    return slot < slot_count() ? pigment_mm.data() + static_cast<std::size_t>(slot) * kTileCells
                               : nullptr;
  }
};

// The part of one tile that a dry layer holds. Only slots with paint in that tile are kept.
struct DryTile {
  int tile_index = 0;
  std::vector<float> volume_mm;     // kTileCells values
  std::vector<std::uint8_t> slots;  // which painting slots are stored, ascending
  std::vector<float> pigment_mm;    // slots.size() * kTileCells, in the order of `slots`

  // Amounts of painting slot `slot` in this tile, or nullptr when it has none.
  const float* pigment(int slot) const;
};

// A dry layer: the tiles that had wet paint when it was dried, sorted by tile index.
struct DryLayer {
  std::vector<DryTile> tiles;
  const DryTile* find(int tile_index) const;  // nullptr when the layer has nothing there
};

class Canvas {
 public:
  explicit Canvas(CanvasSpec spec);

  const CanvasSpec& spec() const { return spec_; }
  double cell_mm() const { return spec_.cell_mm(); }
  int width_cells() const { return spec_.width_cells; }
  int height_cells() const { return spec_.height_cells; }

  // The tile grid.
  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  int tile_count() const { return tiles_x_ * tiles_y_; }
  int tile_index(int tx, int ty) const { return ty * tiles_x_ + tx; }
  // A tile, or nullptr when nothing was ever painted there (then wet and dry are zero and the
  // base height is canvas_weave_height_mm()).
  const Tile* tile(int index) const { return tiles_[static_cast<std::size_t>(index)].get(); }
  const Tile* tile(int tx, int ty) const { return tile(tile_index(tx, ty)); }
  std::size_t allocated_tiles() const;

  // Per-cell reads (x, y in cells, inside the canvas).
  float base_height_mm(int x, int y) const;
  float dry_height_mm(int x, int y) const;
  float wet_volume_mm(int x, int y) const;
  float pigment_mm(int x, int y, int slot) const;

  const std::vector<DryLayer>& dry_layers() const { return dry_layers_; }
  // Cracks in the dry paint and the ground, by canvas tile (empty: an uncracked canvas).
  const CrackLayer& cracks() const { return cracks_; }

  // The tile's cells that lie inside the canvas.
  CellRect tile_cells(int index) const;

  // --- for the simulation (a Painting hands out only a const Canvas) ---
  std::unique_ptr<Tile>& tile_slot(int index) { return tiles_[static_cast<std::size_t>(index)]; }
  Tile& ensure_tile(int index, int slot_count);  // allocates (with its weave) when missing
  std::unique_ptr<Tile> make_tile(int index, int slot_count) const;
  // The weave heights of tile `index` (kTileCells values, zero outside the canvas).
  void compute_base_heights(int index, float* out) const;
  std::vector<DryLayer>& dry_layers() { return dry_layers_; }
  CrackLayer& cracks() { return cracks_; }
  // Tile `index` changed: every cell of it, or only `cells` (clipped to the tile; the stepper
  // knows each step's window).
  void mark_dirty(int index);
  void mark_dirty(int index, const CellRect& cells);
  // What was marked since the previous take, for the painting that owns this canvas to hand
  // on to its subscribers (Painting::take_changes); leaves the set empty.
  std::vector<DirtyTile> take_changes() { return changes_.take(); }

 private:
  CanvasSpec spec_;
  int tiles_x_ = 0;
  int tiles_y_ = 0;
  std::vector<std::unique_ptr<Tile>> tiles_;
  std::vector<DryLayer> dry_layers_;
  CrackLayer cracks_;
  ChangedCells changes_;
};

}  // namespace impasto::paintcore
