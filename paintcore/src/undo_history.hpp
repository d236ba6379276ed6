#pragma once
// Undo/redo by tile snapshots. Before an operation first changes a tile, the tile is copied
// (or noted as absent); the brush, the ledger and the number of dry layers are saved when
// the operation begins. Undo swaps the saved state with the current one, so the step then
// holds what redo needs, and vice versa.
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "ledger.hpp"

namespace impasto::paintcore {

struct UndoStep {
  std::vector<std::pair<int, std::unique_ptr<Tile>>> tiles;  // nullptr: the tile was absent
  Brush brush;
  Ledger ledger;
  std::vector<std::string> slots;    // the pigment slot table
  std::size_t dry_layer_count = 0;   // layers before the operation
  std::vector<DryLayer> dry_layers;  // after undo: the layers the operation had added
  // A reframe (crop or resize) keeps the whole canvas of the other size; undo and redo swap
  // it with the painting's (then `tiles` is empty).
  std::unique_ptr<Canvas> canvas;
  std::size_t bytes = 0;
};

class UndoHistory {
 public:
  // Starts recording an operation on a canvas of `tile_count` tiles.
  void begin(const Brush& brush, const Ledger& ledger, const std::vector<std::string>& slots,
             std::size_t dry_layers, int tile_count);
  bool recording() const { return recording_; }
  // Saves tile `index` unless this operation saved it already.
  void before_tile_change(int index, const Tile* current);
  // The tile as this operation found it, when the operation saved it (nullptr inside: the
  // tile was absent); nullopt when the operation has not changed that tile.
  std::optional<const Tile*> saved_tile(int index) const;
  // Keeps the whole canvas as it was before this operation replaced it (a reframe).
  void keep_canvas(std::unique_ptr<Canvas> before);
  // Ends the operation: it becomes the newest undo step and the redo list is cleared.
  void commit();
  void discard() {
    recording_ = false;
    current_ = UndoStep{};
  }

  // Undo/redo apply to the canvas, brush and ledger given; they return false when empty.
  bool undo(Canvas& canvas, Brush& brush, Ledger& ledger, std::vector<std::string>& slots);
  bool redo(Canvas& canvas, Brush& brush, Ledger& ledger, std::vector<std::string>& slots);

  // The steps, oldest first (undo) and farthest first (redo: back() is redone next), for the
  // painting file; restore() replaces them with steps read back (and keeps the budget).
  const std::deque<UndoStep>& undo_steps() const { return undo_; }
  const std::deque<UndoStep>& redo_steps() const { return redo_; }
  void restore(std::deque<UndoStep> undo, std::deque<UndoStep> redo);

  void set_budget_bytes(std::size_t bytes);
  std::size_t budget_bytes() const { return budget_; }
  std::size_t bytes() const;
  std::size_t undo_depth() const { return undo_.size(); }
  std::size_t redo_depth() const { return redo_.size(); }

 private:
  void enforce_budget();
  static void swap_state(UndoStep& step, Canvas& canvas, Brush& brush, Ledger& ledger,
                         std::vector<std::string>& slots);

  bool recording_ = false;
  UndoStep current_;
  std::vector<std::uint32_t> saved_in_op_;  // op id per tile that was saved
  std::vector<std::uint32_t> saved_at_;     // and where in current_.tiles (no search per cell)
  std::uint32_t op_id_ = 0;
  std::deque<UndoStep> undo_;
  std::deque<UndoStep> redo_;
  std::size_t budget_ = std::size_t{512} << 20;
};

std::size_t tile_bytes(const Tile& tile);
std::size_t brush_bytes(const Brush& brush);
std::size_t dry_layer_bytes(const DryLayer& layer);
std::size_t canvas_bytes(const Canvas& canvas);  // tiles, dry layers and cracks

}  // namespace impasto::paintcore
