#include "impasto/paintcore/canvas_reframe.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "impasto/paintcore/paint_surface.hpp"

namespace impasto::paintcore {
namespace {

struct AnchorName {
  CanvasAnchor anchor;
  const char* name;
  int fx, fy;  // where the old canvas sits along each axis: 0 start, 1 middle, 2 end
};

constexpr std::array<AnchorName, 9> kAnchors = {{
    {CanvasAnchor::kTopLeft, "top-left", 0, 0},
    {CanvasAnchor::kTop, "top", 1, 0},
    {CanvasAnchor::kTopRight, "top-right", 2, 0},
    {CanvasAnchor::kLeft, "left", 0, 1},
    {CanvasAnchor::kCenter, "center", 1, 1},
    {CanvasAnchor::kRight, "right", 2, 1},
    {CanvasAnchor::kBottomLeft, "bottom-left", 0, 2},
    {CanvasAnchor::kBottom, "bottom", 1, 2},
    {CanvasAnchor::kBottomRight, "bottom-right", 2, 2},
}};

const AnchorName& anchor_entry(CanvasAnchor anchor) {
  for (const AnchorName& a : kAnchors)
    if (a.anchor == anchor) return a;
  return kAnchors[4];
}

// Offset along one axis: 0 keeps the start, the middle splits the change (the odd cell goes
// to the end), the end keeps the end.
int anchored_offset(int old_size, int size, int where) {
  const int change = size - old_size;
  return where == 0 ? 0 : where == 1 ? change / 2 : change;
}

// The crack records, tile by tile, moved to the new frame.
void move_cracks(const Canvas& from, const CanvasFrame& frame, Canvas& to) {
  const CrackLayer& cracks = from.cracks();
  for (int index = 0; index < cracks.tile_extent(); ++index) {
    const CrackTile* tile = cracks.tile(index);
    if (!tile) continue;
    const int x0 = (index % from.tiles_x()) * kTileSize;
    const int y0 = (index / from.tiles_x()) * kTileSize;
    for (int c = 0; c < kTileCells; ++c) {
      const CrackRecord& r = tile->cells[static_cast<std::size_t>(c)];
      if (!r.has_crack()) continue;
      const int nx = x0 + c % kTileSize + frame.offset_x_cells;
      const int ny = y0 + c / kTileSize + frame.offset_y_cells;
      if (nx < 0 || ny < 0 || nx >= to.width_cells() || ny >= to.height_cells()) continue;
      CrackTile& target = to.cracks().ensure_tile(to.tile_index(nx / kTileSize, ny / kTileSize));
      target.cells[static_cast<std::size_t>((ny % kTileSize) * kTileSize + nx % kTileSize)] = r;
    }
  }
}

// A dry layer being gathered into the new frame: whole slot planes per new tile.
struct DryGather {
  std::vector<float> volume = std::vector<float>(kTileCells, 0.0f);
  std::map<int, std::vector<float>> pigment;  // slot -> kTileCells values
};

DryLayer move_dry_layer(const DryLayer& layer, const Canvas& from, const CanvasFrame& frame,
                        const Canvas& to, CutPaint& cut) {
  std::map<int, DryGather> gathered;
  for (const DryTile& tile : layer.tiles) {
    const int x0 = (tile.tile_index % from.tiles_x()) * kTileSize;
    const int y0 = (tile.tile_index / from.tiles_x()) * kTileSize;
    for (int c = 0; c < kTileCells; ++c) {
      const int x = x0 + c % kTileSize, y = y0 + c / kTileSize;
      if (x >= from.width_cells() || y >= from.height_cells()) continue;
      const int nx = x + frame.offset_x_cells, ny = y + frame.offset_y_cells;
      const auto cell = static_cast<std::size_t>(c);
      if (nx < 0 || ny < 0 || nx >= to.width_cells() || ny >= to.height_cells()) {
        cut.volume_mm += tile.volume_mm[cell];
        for (std::size_t k = 0; k < tile.slots.size(); ++k)
          cut.pigment_mm[tile.slots[k]] += tile.pigment_mm[k * kTileCells + cell];
        continue;
      }
      DryGather& g = gathered[to.tile_index(nx / kTileSize, ny / kTileSize)];
      const auto target = static_cast<std::size_t>((ny % kTileSize) * kTileSize + nx % kTileSize);
      g.volume[target] = tile.volume_mm[cell];
      for (std::size_t k = 0; k < tile.slots.size(); ++k) {
        auto& plane = g.pigment[tile.slots[k]];
        if (plane.empty()) plane.assign(kTileCells, 0.0f);
        plane[target] = tile.pigment_mm[k * kTileCells + cell];
      }
    }
  }
  DryLayer moved;
  for (auto& [index, g] : gathered) {  // std::map: ascending tile order, as a layer keeps it
    DryTile tile;
    tile.tile_index = index;
    tile.volume_mm = std::move(g.volume);
    for (auto& [slot, plane] : g.pigment) {
      if (std::none_of(plane.begin(), plane.end(), [](float v) { return v != 0.0f; })) continue;
      tile.slots.push_back(static_cast<std::uint8_t>(slot));
      tile.pigment_mm.insert(tile.pigment_mm.end(), plane.begin(), plane.end());
    }
    moved.tiles.push_back(std::move(tile));
  }
  return moved;
}

}  // namespace

CanvasAnchor parse_canvas_anchor(const std::string& name) {
  if (name == "centre") return CanvasAnchor::kCenter;
  for (const AnchorName& a : kAnchors)
    if (name == a.name) return a.anchor;
  std::string choices;
  for (const AnchorName& a : kAnchors) choices += std::string(choices.empty() ? "" : ", ") + a.name;
  throw std::runtime_error("canvas anchor: '" + name + "' is not one of " + choices);
}

const char* canvas_anchor_name(CanvasAnchor anchor) {
  return anchor_entry(anchor).name;
}

CanvasFrame anchored_frame(int old_width, int old_height, int width, int height,
                           CanvasAnchor anchor) {
  const AnchorName& a = anchor_entry(anchor);
  return {width, height, anchored_offset(old_width, width, a.fx),
          anchored_offset(old_height, height, a.fy)};
}

CanvasFrame crop_frame(int x, int y, int width, int height) {
  return {width, height, -x, -y};
}

void validate(const CanvasFrame& frame, const CanvasSpec& old_spec) {
  const auto fail = [](const std::string& field, const std::string& why) {
    throw std::runtime_error("canvas frame: field '" + field + "' " + why);
  };
  if (frame.width_cells <= 0 || frame.width_cells > kMaxCanvasCells)
    fail("width_cells", "must be in 1.." + std::to_string(kMaxCanvasCells) + ", got " +
                            std::to_string(frame.width_cells));
  if (frame.height_cells <= 0 || frame.height_cells > kMaxCanvasCells)
    fail("height_cells", "must be in 1.." + std::to_string(kMaxCanvasCells) + ", got " +
                             std::to_string(frame.height_cells));
  // The old canvas must overlap the new one: a frame beside it would keep nothing.
  const auto overlaps = [](int offset, int old_size, int size) {
    return offset < size && offset + old_size > 0;
  };
  if (!overlaps(frame.offset_x_cells, old_spec.width_cells, frame.width_cells))
    fail("offset_x_cells", std::to_string(frame.offset_x_cells) +
                               " leaves no column of the old canvas in the new one");
  if (!overlaps(frame.offset_y_cells, old_spec.height_cells, frame.height_cells))
    fail("offset_y_cells",
         std::to_string(frame.offset_y_cells) + " leaves no row of the old canvas in the new one");
}

CanvasSpec reframed_spec(const CanvasSpec& spec, const CanvasFrame& frame) {
  CanvasSpec next = spec;
  next.width_cells = frame.width_cells;
  next.height_cells = frame.height_cells;
  next.weave_origin_x_cells -= frame.offset_x_cells;
  next.weave_origin_y_cells -= frame.offset_y_cells;
  return next;
}

Canvas reframed_canvas(const Canvas& canvas, const CanvasFrame& frame, int slot_count,
                       CutPaint& cut) {
  validate(frame, canvas.spec());
  Canvas next(reframed_spec(canvas.spec(), frame));
  cut = CutPaint{0.0, std::vector<double>(256, 0.0)};  // any uint8 slot a dry tile names
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!tile) continue;
    const int slots = tile->slot_count();
    const int x0 = (index % canvas.tiles_x()) * kTileSize;
    const int y0 = (index / canvas.tiles_x()) * kTileSize;
    const int nx_cells = std::min(kTileSize, canvas.width_cells() - x0);
    const int ny_cells = std::min(kTileSize, canvas.height_cells() - y0);
    for (int ly = 0; ly < ny_cells; ++ly)
      for (int lx = 0; lx < nx_cells; ++lx) {
        const auto c = static_cast<std::size_t>(ly * kTileSize + lx);
        const int nx = x0 + lx + frame.offset_x_cells, ny = y0 + ly + frame.offset_y_cells;
        if (nx < 0 || ny < 0 || nx >= next.width_cells() || ny >= next.height_cells()) {
          cut.volume_mm += tile->wet_volume_mm[c];  // the dry part is counted by its layers
          for (int s = 0; s < slots; ++s)
            cut.pigment_mm[static_cast<std::size_t>(s)] += tile->pigment(s)[c];
          continue;
        }
        const int target_index = next.tile_index(nx / kTileSize, ny / kTileSize);
        Tile& target = next.ensure_tile(target_index, std::max(slots, slot_count));
        const auto t = static_cast<std::size_t>((ny % kTileSize) * kTileSize + nx % kTileSize);
        target.dry_height_mm[t] = tile->dry_height_mm[c];
        target.wet_volume_mm[t] = tile->wet_volume_mm[c];
        for (int s = 0; s < slots; ++s) target.pigment(s)[t] = tile->pigment(s)[c];
        copy_cell_surface(tile, static_cast<int>(c), target, static_cast<int>(t));
      }
  }
  for (const DryLayer& layer : canvas.dry_layers())
    next.dry_layers().push_back(move_dry_layer(layer, canvas, frame, next, cut));
  move_cracks(canvas, frame, next);
  cut.pigment_mm.resize(static_cast<std::size_t>(slot_count));
  for (int index = 0; index < next.tile_count(); ++index) next.mark_dirty(index);  // all moved
  return next;
}

}  // namespace impasto::paintcore
