#include "painting_history_file.hpp"

#include <vector>

#include "brush_head_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "painting_surface_file.hpp"

namespace impasto::paintcore {
using namespace file_io;  // NOLINT: the file's own building blocks

namespace {

using W = Writer<ByteSink>;

void write_totals_of(W& w, const PaintTotals& t) {
  w.put(static_cast<std::uint32_t>(t.pigment.size()));
  w.put(t.volume);
  for (double v : t.pigment) w.put(v);
}

PaintTotals read_totals_of(Reader& r, const std::string& field) {
  PaintTotals t;
  const auto n = r.get_count(field + ".count", 256, 8);
  t.volume = r.get_finite(field + ".volume");
  for (std::uint32_t s = 0; s < n; ++s) t.pigment.push_back(r.get_finite(field + ".pigment"));
  return t;
}

// From version 8 a step's tile is stored against the same tile's next newer state (in a step
// written before it, or the painting itself): each plane as the XOR of its bits with the newer
// one's, so that the cells the step did not change are zeros, which compression all but
// removes. Null where there is no newer state (or it lacks that slot).
const float* newer_plane(const Tile* newer, const float* (*plane)(const Tile&)) {
  return newer != nullptr ? plane(*newer) : nullptr;
}
const float* dry_plane(const Tile& t) {
  return t.dry_height_mm.data();
}
const float* wet_plane(const Tile& t) {
  return t.wet_volume_mm.data();
}
const float* newer_pigment(const Tile* newer, int slot) {
  return newer != nullptr ? newer->pigment(slot) : nullptr;
}

// A tile in any slot count (a step keeps it as it was).
void write_tile(W& w, const Tile& tile, const Tile* newer) {
  w.put(static_cast<std::uint8_t>(tile.slot_count() |
                                  (surface_planes(tile) << kHistorySurfaceShift)));
  w.put_floats(tile.dry_height_mm.data(), kTileCells, newer_plane(newer, dry_plane));
  w.put_floats(tile.wet_volume_mm.data(), kTileCells, newer_plane(newer, wet_plane));
  for (int s = 0; s < tile.slot_count(); ++s)
    w.put_floats(tile.pigment(s), kTileCells, newer_pigment(newer, s));
  write_surface_planes(w, tile);  // media and varnish (painting_surface_file.hpp)
}

std::unique_ptr<Tile> read_tile(Reader& r, const Canvas& frame_canvas, int index,
                                const std::string& field, const Tile* newer) {
  const auto byte = r.get<std::uint8_t>(field + ".slot_count");
  const int slots = byte & ((1 << kHistorySurfaceShift) - 1);
  if (slots > kMaxPigmentSlots) r.fail(field + ".slot_count", "more than 16 slots");
  auto tile = frame_canvas.make_tile(index, slots);
  r.get_amounts(tile->dry_height_mm.data(), kTileCells, field + ".dry_height",
                newer_plane(newer, dry_plane));
  r.get_amounts(tile->wet_volume_mm.data(), kTileCells, field + ".wet_volume",
                newer_plane(newer, wet_plane));
  for (int s = 0; s < slots; ++s)
    r.get_amounts(tile->pigment(s), kTileCells, field + ".pigment", newer_pigment(newer, s));
  repair_pigment(tile->wet_volume_mm.data(), tile->pigment_mm.data(), slots, kTileCells);
  read_surface_planes(r, *tile, static_cast<std::uint8_t>(byte >> kHistorySurfaceShift), field);
  return tile;
}

// The newest state of each tile of a frame seen so far, while steps are written or read
// outward from the painting (empty: the file's version does not code against it).
struct NewerTiles {
  bool coded = false;
  std::vector<const Tile*> tiles;

  void start_from(const Canvas& canvas) {
    tiles.assign(static_cast<std::size_t>(canvas.tile_count()), nullptr);
    for (int index = 0; index < canvas.tile_count(); ++index)
      tiles[static_cast<std::size_t>(index)] = canvas.tile(index);
  }
  const Tile* of(int index) const {
    return coded ? tiles[static_cast<std::size_t>(index)] : nullptr;
  }
  // After a step: its tiles are the newest states of theirs; a reframe's canvas of all.
  void after(const UndoStep& step) {
    if (step.canvas) return start_from(*step.canvas);
    for (const auto& [index, tile] : step.tiles)
      tiles[static_cast<std::size_t>(index)] = tile.get();
  }
};

void write_brush(W& w, const Brush& brush) {
  // 2: the paint on it has a medium, written last (painting_surface_file.hpp).
  const bool medium = brush.medium() != PaintMedium{};
  w.put(static_cast<std::uint8_t>(brush.empty() ? 0 : medium ? 2 : 1));
  if (brush.empty()) return;
  write_brush_head(w, brush.head());
  write_bristles(w, brush.head());
  write_brush_settings(w, brush.settings());
  w.put(static_cast<std::uint8_t>(brush.body()));
  w.put(static_cast<std::uint32_t>(brush.cells_across()));
  w.put(static_cast<std::uint8_t>(brush.slot_count()));
  w.put_floats(brush.volume_mm().data(), brush.cell_count());
  w.put_floats(brush.pigment_mm().data(), brush.pigment_mm().size());
  if (medium) write_brush_medium(w, brush);
}

Brush read_brush(Reader& r, double cell_mm, const std::string& field) {
  const auto present = r.get<std::uint8_t>(field + ".present");
  if (present == 0) return Brush();
  BrushHead head = read_brush_head(r, field + ".head");
  read_bristles(r, field + ".head", head);
  const BrushSettings settings = read_brush_settings(r, field + ".settings");
  const auto body = r.get<std::uint8_t>(field + ".body");
  if (body >= kPaintBodies.size()) r.fail(field + ".body", "unknown paint body");
  const auto across = r.get<std::uint32_t>(field + ".cells_across");
  const auto slots = r.get<std::uint8_t>(field + ".slot_count");
  if (slots > kMaxPigmentSlots) r.fail(field + ".slot_count", "more than 16 slots");
  Brush brush;
  try {
    brush = Brush(head, settings, cell_mm, slots);
  } catch (const std::exception& e) {
    r.fail(field, e.what());
  }
  if (across != static_cast<std::uint32_t>(brush.cells_across()))
    r.fail(field + ".cells_across", "does not match the brush size");
  r.get_amounts(brush.volume_mm().data(), brush.cell_count(), field + ".volume");
  r.get_amounts(brush.pigment_mm().data(), brush.pigment_mm().size(), field + ".pigment");
  repair_pigment(brush.volume_mm().data(), brush.pigment_mm().data(), slots, brush.cell_count());
  brush.set_body(static_cast<PaintBody>(body));
  if (present == 2) read_brush_medium(r, brush, field + ".medium");
  return brush;
}

void write_frame(W& w, const CanvasSpec& spec) {
  w.put(static_cast<std::int32_t>(spec.width_cells));
  w.put(static_cast<std::int32_t>(spec.height_cells));
  w.put(spec.weave_origin_x_cells);
  w.put(spec.weave_origin_y_cells);
}

// A whole canvas kept by a reframe step.
void write_canvas(W& w, const Canvas& canvas) {
  write_frame(w, canvas.spec());
  w.put(static_cast<std::uint32_t>(canvas.allocated_tiles()));
  for (int index = 0; index < canvas.tile_count(); ++index)
    if (const Tile* tile = canvas.tile(index)) {
      w.put(static_cast<std::uint32_t>(index));
      write_tile(w, *tile, nullptr);
    }
  w.put(static_cast<std::uint32_t>(canvas.dry_layers().size()));
  for (const DryLayer& layer : canvas.dry_layers()) write_dry_layer(w, layer);
  write_cracks(w, canvas.cracks());
}

std::unique_ptr<Canvas> read_canvas(Reader& r, const CanvasSpec& painting, const std::string& field,
                                    const std::string& file, std::uint64_t& table_bytes) {
  CanvasSpec spec = painting;
  spec.width_cells = r.get<std::int32_t>(field + ".width_cells");
  spec.height_cells = r.get<std::int32_t>(field + ".height_cells");
  spec.weave_origin_x_cells = r.get<std::int64_t>(field + ".weave_origin_x_cells");
  spec.weave_origin_y_cells = r.get<std::int64_t>(field + ".weave_origin_y_cells");
  try {
    validate(spec);
  } catch (const std::exception& e) {
    r.fail(field, e.what());
  }
  // Each kept canvas has a tile table of its declared size, whatever its tiles: a crafted
  // history of many huge frames must fail by name, not exhaust memory.
  const auto tiles_along = [](int cells) {
    return static_cast<std::uint64_t>(cells + kTileSize - 1) / kTileSize;
  };
  table_bytes += tiles_along(spec.width_cells) * tiles_along(spec.height_cells) *
                 (sizeof(std::unique_ptr<Tile>) + 1);
  files::check_allocation(file, "the undo history's canvases (" + field + ")", table_bytes);
  auto canvas = std::make_unique<Canvas>(spec);
  const int tile_count = canvas->tile_count();
  const auto tiles =
      r.get_count(field + ".tiles.count", static_cast<std::uint32_t>(tile_count), kMinWetTileBytes);
  int previous = -1;
  for (std::uint32_t k = 0; k < tiles; ++k) {
    const std::string tfield = field + ".tiles[" + std::to_string(k) + "]";
    const auto index = static_cast<int>(
        r.get_count(tfield + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (index <= previous) r.fail(tfield + ".index", "tiles are not in ascending order");
    previous = index;
    canvas->tile_slot(index) = read_tile(r, *canvas, index, tfield, nullptr);
  }
  const auto layers = r.get_count(field + ".dry_layers.count", 1u << 24, 4);
  for (std::uint32_t l = 0; l < layers; ++l)
    canvas->dry_layers().push_back(read_dry_layer(
        r, field + ".dry_layers[" + std::to_string(l) + "]", tile_count, kMaxPigmentSlots));
  canvas->cracks() = read_cracks(r, *canvas, file);
  return canvas;
}

void write_step(W& w, const UndoStep& step, const NewerTiles& newer) {
  w.put(static_cast<std::uint32_t>(step.dry_layer_count));
  w.put(static_cast<std::uint32_t>(step.slots.size()));
  for (const std::string& name : step.slots) w.put_string(name);
  write_totals_of(w, step.ledger.loaded);
  write_totals_of(w, step.ledger.wiped);
  write_brush(w, step.brush);
  w.put(static_cast<std::uint32_t>(step.tiles.size()));
  for (const auto& [index, tile] : step.tiles) {
    w.put(static_cast<std::uint32_t>(index));
    w.put(static_cast<std::uint8_t>(tile ? 1 : 0));
    if (tile) write_tile(w, *tile, newer.of(index));
  }
  w.put(static_cast<std::uint32_t>(step.dry_layers.size()));
  for (const DryLayer& layer : step.dry_layers) write_dry_layer(w, layer);
  w.put(static_cast<std::uint8_t>(step.canvas ? 1 : 0));
  if (step.canvas) write_canvas(w, *step.canvas);
}

// Where undo or redo stands while the steps are read: the canvas a step applies to and its
// number of dry layers.
struct Chain {
  std::unique_ptr<Canvas> frame;  // an empty canvas of the step's frame (for its weave)
  std::size_t layers = 0;
  std::uint64_t table_bytes = 0;  // the kept canvases' tile tables, both ways
  NewerTiles newer;
};

void set_frame(Chain& chain, const CanvasSpec& spec) {
  const CanvasSpec& now = chain.frame->spec();
  if (now.width_cells == spec.width_cells && now.height_cells == spec.height_cells &&
      now.weave_origin_x_cells == spec.weave_origin_x_cells &&
      now.weave_origin_y_cells == spec.weave_origin_y_cells)
    return;
  chain.frame = std::make_unique<Canvas>(spec);
}

UndoStep read_step(Reader& r, const std::string& field, bool is_redo, Chain& chain,
                   const CanvasSpec& painting, const std::string& file) {
  UndoStep step;
  step.dry_layer_count = r.get<std::uint32_t>(field + ".dry_layer_count");
  const auto slots = r.get_count(field + ".slots.count", kMaxPigmentSlots);
  for (std::uint32_t s = 0; s < slots; ++s) {
    step.slots.push_back(r.get_string(field + ".slots[" + std::to_string(s) + "]"));
    if (step.slots.back().empty()) r.fail(field + ".slots", "empty pigment name");
  }
  step.ledger.loaded = read_totals_of(r, field + ".ledger.loaded");
  step.ledger.wiped = read_totals_of(r, field + ".ledger.wiped");
  step.brush = read_brush(r, painting.cell_mm(), field + ".brush");
  step.bytes = brush_bytes(step.brush);
  const int tile_count = chain.frame->tile_count();
  const auto tiles = r.get_count(field + ".tiles.count", static_cast<std::uint32_t>(tile_count), 5);
  std::vector<bool> seen(static_cast<std::size_t>(tile_count), false);
  for (std::uint32_t k = 0; k < tiles; ++k) {
    const std::string tfield = field + ".tiles[" + std::to_string(k) + "]";
    const auto index = static_cast<int>(
        r.get_count(tfield + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (seen[static_cast<std::size_t>(index)]) r.fail(tfield + ".index", "a tile appears twice");
    seen[static_cast<std::size_t>(index)] = true;
    std::unique_ptr<Tile> tile;
    if (r.get<std::uint8_t>(tfield + ".present") != 0)
      tile = read_tile(r, *chain.frame, index, tfield, chain.newer.of(index));
    step.bytes += tile ? tile_bytes(*tile) : sizeof(std::pair<int, std::unique_ptr<Tile>>);
    step.tiles.emplace_back(index, std::move(tile));
  }
  const auto added_layers = r.get_count(field + ".dry_layers.count", 1u << 24, 4);
  if (!is_redo && added_layers != 0)
    r.fail(field + ".dry_layers.count", "an undo step holds no added layers");
  std::vector<DryLayer> added;
  for (std::uint32_t l = 0; l < added_layers; ++l)
    added.push_back(read_dry_layer(r, field + ".dry_layers[" + std::to_string(l) + "]",
                                   chain.frame->tile_count(), static_cast<int>(slots)));
  if (r.get<std::uint8_t>(field + ".has_canvas") != 0) {
    if (!step.tiles.empty() || !added.empty())
      r.fail(field + ".has_canvas", "a reframe step holds no tiles or layers of its own");
    step.canvas = read_canvas(r, painting, field + ".canvas", file, chain.table_bytes);
    step.bytes += canvas_bytes(*step.canvas);
  }
  // The step against the state it applies to. Undo erases the layers from dry_layer_count
  // on; redo adds its own to exactly dry_layer_count; a reframe keeps the number of layers,
  // so none of one frame's layers can land on the other's canvas.
  const auto layer_mismatch = [&](std::size_t layers) {
    r.fail(field + ".dry_layer_count", std::to_string(step.dry_layer_count) +
                                           " does not match the " + std::to_string(layers) +
                                           " dry layers it applies to");
  };
  if (step.canvas && step.dry_layer_count != step.canvas->dry_layers().size())
    layer_mismatch(step.canvas->dry_layers().size());
  if (is_redo ? step.dry_layer_count != chain.layers : step.dry_layer_count > chain.layers)
    layer_mismatch(chain.layers);
  if (step.canvas) set_frame(chain, step.canvas->spec());
  chain.layers = step.dry_layer_count + (is_redo ? added.size() : 0);
  for (const DryLayer& layer : added) step.bytes += dry_layer_bytes(layer);
  step.dry_layers = std::move(added);
  chain.newer.after(step);
  return step;
}

}  // namespace

SavedSteps steps_to_save(const UndoHistory& history, std::size_t budget) {
  SavedSteps kept;
  std::size_t bytes = 0;
  const auto& undo = history.undo_steps();
  for (auto it = undo.rbegin(); it != undo.rend() && bytes + it->bytes <= budget; ++it) {
    bytes += it->bytes;
    ++kept.undo;
  }
  const auto& redo = history.redo_steps();
  for (auto it = redo.rbegin(); it != redo.rend() && bytes + it->bytes <= budget; ++it) {
    bytes += it->bytes;
    ++kept.redo;
  }
  return kept;
}

void write_history(const Canvas& canvas, const UndoHistory& history, SavedSteps steps, W& w) {
  w.put(static_cast<std::uint64_t>(steps.undo));
  w.put(static_cast<std::uint64_t>(steps.redo));
  // Nearest first, each way: reading follows the canvas from now into the past and future.
  NewerTiles newer{true, {}};
  newer.start_from(canvas);
  const auto& undo = history.undo_steps();
  for (std::size_t k = 0; k < steps.undo; ++k) {
    const UndoStep& step = undo[undo.size() - 1 - k];
    write_step(w, step, newer);
    newer.after(step);
  }
  newer.start_from(canvas);
  const auto& redo = history.redo_steps();
  for (std::size_t k = 0; k < steps.redo; ++k) {
    const UndoStep& step = redo[redo.size() - 1 - k];
    write_step(w, step, newer);
    newer.after(step);
  }
}

void read_history(const Canvas& canvas, UndoHistory& history, Reader& r, const std::string& file,
                  std::uint32_t version) {
  const CanvasSpec& painting = canvas.spec();
  constexpr std::uint64_t kMinStepBytes = 4 + 4 + 2 * 12 + 1 + 4 + 4 + 1;
  const auto undo_count = r.get<std::uint64_t>("history.undo_count");
  const auto redo_count = r.get<std::uint64_t>("history.redo_count");
  if (undo_count > r.left() / kMinStepBytes || redo_count > r.left() / kMinStepBytes ||
      undo_count + redo_count > r.left() / kMinStepBytes)
    r.fail("history.undo_count", "the steps do not fit in the section (a crafted file)");
  std::deque<UndoStep> undo, redo;
  const bool coded = version >= kCompressedVersion;
  const auto chain_from_now = [&](std::uint64_t table_bytes) {
    Chain chain{std::make_unique<Canvas>(painting), canvas.dry_layers().size(), table_bytes,
                NewerTiles{coded, {}}};
    chain.newer.start_from(canvas);
    return chain;
  };
  Chain chain = chain_from_now(0);
  for (std::uint64_t k = 0; k < undo_count; ++k)
    undo.push_front(
        read_step(r, "history.undo[" + std::to_string(k) + "]", false, chain, painting, file));
  chain = chain_from_now(chain.table_bytes);
  for (std::uint64_t k = 0; k < redo_count; ++k)
    redo.push_front(
        read_step(r, "history.redo[" + std::to_string(k) + "]", true, chain, painting, file));
  if (!r.at_end()) r.fail("history.end", "unexpected bytes after the last step");
  history.restore(std::move(undo), std::move(redo));
}

}  // namespace impasto::paintcore
