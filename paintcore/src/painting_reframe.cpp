// Painting::reframe_canvas: the canvas's size as one undoable operation (canvas_reframe.hpp).
#include "impasto/paintcore/canvas_reframe.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {

PaintTotals Painting::reframe_canvas(const CanvasFrame& frame) {
  Impl& p = *impl_;
  validate(frame, p.canvas.spec());  // before anything changes
  const bool same = frame.width_cells == p.canvas.width_cells() &&
                    frame.height_cells == p.canvas.height_cells() && frame.offset_x_cells == 0 &&
                    frame.offset_y_cells == 0;
  if (same) return PaintTotals{0.0, std::vector<double>(p.slots.size(), 0.0)};  // no step
  end_stroke();
  CutPaint cut;
  Canvas next = reframed_canvas(p.canvas, frame, slot_count(), cut);
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  const CanvasSpec before = p.canvas.spec();
  p.history.keep_canvas(std::make_unique<Canvas>(std::move(p.canvas)));
  p.canvas = std::move(next);
  p.forget_weave_cache_if_reframed(before);
  const double area = p.canvas.spec().cell_area_mm2();
  PaintTotals removed{cut.volume_mm * area, {}};
  for (double amount : cut.pigment_mm) removed.pigment.push_back(amount * area);
  accumulate(p.ledger.wiped, removed);
  p.history.commit();
  return removed;
}

Painting Painting::cropped(const CanvasFrame& frame) const {
  const Impl& p = *impl_;
  validate(frame, p.canvas.spec());
  std::unique_ptr<Impl> band = p.resampled(reframed_spec(p.canvas.spec(), frame));
  CutPaint cut;
  band->canvas = reframed_canvas(p.canvas, frame, slot_count(), cut);
  band->canvas.cracks() = CrackLayer{};  // not carried, as refined and coarsened do not
  return Painting(std::move(band));
}

void Painting::set_saved_history_bytes(std::size_t bytes) {
  impl_->saved_history_bytes = bytes;
}

std::size_t Painting::saved_history_bytes() const {
  return impl_->saved_history_bytes;
}

const std::string& Painting::load_warning() const {
  return impl_->load_warning;
}

}  // namespace impasto::paintcore
