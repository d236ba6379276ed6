#include "undo_history.hpp"

#include <algorithm>

namespace impasto::paintcore {

std::size_t tile_bytes(const Tile& tile) {
  return sizeof(Tile) +
         (tile.pigment_mm.capacity() + tile.medium.capacity() + tile.varnish.capacity()) *
             sizeof(float);
}

std::size_t brush_bytes(const Brush& brush) {
  return sizeof(Brush) +
         (brush.footprint_mm().capacity() + brush.volume_mm().capacity() +
          brush.pigment_mm().capacity()) *
             sizeof(float) +
         brush.covers().capacity() + brush.covered_runs().capacity() * sizeof(Brush::CellRun);
}

std::size_t dry_layer_bytes(const DryLayer& layer) {
  std::size_t bytes = sizeof(DryLayer);
  for (const DryTile& t : layer.tiles)
    bytes += sizeof(DryTile) + (t.volume_mm.capacity() + t.pigment_mm.capacity()) * sizeof(float) +
             t.slots.capacity();
  return bytes;
}

std::size_t canvas_bytes(const Canvas& canvas) {
  std::size_t bytes = sizeof(Canvas) + canvas.tile_count() * sizeof(std::unique_ptr<Tile>);
  for (int index = 0; index < canvas.tile_count(); ++index)
    if (const Tile* tile = canvas.tile(index)) bytes += tile_bytes(*tile);
  for (const DryLayer& layer : canvas.dry_layers()) bytes += dry_layer_bytes(layer);
  return bytes + canvas.cracks().memory_bytes();
}

void UndoHistory::keep_canvas(std::unique_ptr<Canvas> before) {
  if (!recording_) return;
  current_.bytes += canvas_bytes(*before);
  current_.canvas = std::move(before);
}

void UndoHistory::begin(const Brush& brush, const Ledger& ledger,
                        const std::vector<std::string>& slots, std::size_t dry_layers,
                        int tile_count) {
  current_ = UndoStep{};
  current_.brush = brush;
  current_.ledger = ledger;
  current_.slots = slots;
  current_.dry_layer_count = dry_layers;
  current_.bytes = brush_bytes(brush);
  saved_in_op_.resize(static_cast<std::size_t>(tile_count), 0);
  saved_at_.resize(static_cast<std::size_t>(tile_count), 0);
  if (++op_id_ == 0) {  // wrapped: forget old ids
    std::fill(saved_in_op_.begin(), saved_in_op_.end(), 0);
    op_id_ = 1;
  }
  recording_ = true;
}

void UndoHistory::before_tile_change(int index, const Tile* current) {
  if (!recording_) return;
  auto& saved = saved_in_op_[static_cast<std::size_t>(index)];
  if (saved == op_id_) return;
  saved = op_id_;
  std::unique_ptr<Tile> copy = current ? std::make_unique<Tile>(*current) : nullptr;
  current_.bytes += copy ? tile_bytes(*copy) : sizeof(std::pair<int, std::unique_ptr<Tile>>);
  saved_at_[static_cast<std::size_t>(index)] = static_cast<std::uint32_t>(current_.tiles.size());
  current_.tiles.emplace_back(index, std::move(copy));
}

std::optional<const Tile*> UndoHistory::saved_tile(int index) const {
  if (!recording_ || saved_in_op_[static_cast<std::size_t>(index)] != op_id_) return std::nullopt;
  return current_.tiles[saved_at_[static_cast<std::size_t>(index)]].second.get();
}

void UndoHistory::commit() {
  if (!recording_) return;
  recording_ = false;
  undo_.push_back(std::move(current_));
  current_ = UndoStep{};
  redo_.clear();
  enforce_budget();
}

void UndoHistory::swap_state(UndoStep& step, Canvas& canvas, Brush& brush, Ledger& ledger,
                             std::vector<std::string>& slots) {
  if (step.canvas) {
    step.bytes -= std::min(step.bytes, canvas_bytes(*step.canvas));
    std::swap(canvas, *step.canvas);
    step.bytes += canvas_bytes(*step.canvas);
    for (int index = 0; index < canvas.tile_count(); ++index) canvas.mark_dirty(index);
  }
  for (auto& [index, tile] : step.tiles) {
    std::swap(canvas.tile_slot(index), tile);
    canvas.mark_dirty(index);
  }
  std::swap(brush, step.brush);
  std::swap(ledger, step.ledger);
  std::swap(slots, step.slots);
}

bool UndoHistory::undo(Canvas& canvas, Brush& brush, Ledger& ledger,
                       std::vector<std::string>& slots) {
  if (undo_.empty()) return false;
  UndoStep step = std::move(undo_.back());
  undo_.pop_back();
  swap_state(step, canvas, brush, ledger, slots);
  auto& layers = canvas.dry_layers();
  const auto first_added = layers.begin() + static_cast<std::ptrdiff_t>(step.dry_layer_count);
  step.dry_layers.assign(std::make_move_iterator(first_added),
                         std::make_move_iterator(layers.end()));
  layers.erase(first_added, layers.end());
  for (const DryLayer& layer : step.dry_layers) step.bytes += dry_layer_bytes(layer);
  redo_.push_back(std::move(step));
  return true;
}

bool UndoHistory::redo(Canvas& canvas, Brush& brush, Ledger& ledger,
                       std::vector<std::string>& slots) {
  if (redo_.empty()) return false;
  UndoStep step = std::move(redo_.back());
  redo_.pop_back();
  swap_state(step, canvas, brush, ledger, slots);
  auto& layers = canvas.dry_layers();
  for (DryLayer& layer : step.dry_layers) {
    step.bytes -= std::min(step.bytes, dry_layer_bytes(layer));
    layers.push_back(std::move(layer));
  }
  step.dry_layers.clear();
  undo_.push_back(std::move(step));
  return true;
}

void UndoHistory::restore(std::deque<UndoStep> undo, std::deque<UndoStep> redo) {
  recording_ = false;
  current_ = UndoStep{};
  undo_ = std::move(undo);
  redo_ = std::move(redo);
  enforce_budget();
}

void UndoHistory::set_budget_bytes(std::size_t bytes) {
  budget_ = bytes;
  enforce_budget();
}

std::size_t UndoHistory::bytes() const {
  std::size_t total = 0;
  for (const auto& s : undo_) total += s.bytes;
  for (const auto& s : redo_) total += s.bytes;
  return total;
}

void UndoHistory::enforce_budget() {
  // Redo steps go first, then the oldest undo steps; the newest undo step always stays.
  while (bytes() > budget_ && !redo_.empty()) redo_.pop_front();
  while (bytes() > budget_ && undo_.size() > 1) undo_.pop_front();
}

}  // namespace impasto::paintcore
