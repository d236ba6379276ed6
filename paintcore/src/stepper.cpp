#include "stepper.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "contact_rows.hpp"
#include "impasto/paintcore/transfer.hpp"
#include "impasto/paintcore/weave.hpp"
#include "parallel_rows.hpp"
#include "simd_clones.hpp"

namespace impasto::paintcore {
namespace {

// The bristles even out once per this many cells travelled (a long step's every step), not
// every one-cell step: it costs a pass over the brush for each quantity. Batched over 0.5 mm
// (5 cells at 254 dpi), they evened out at a rhythm a stroke could show; 4 cells is at
// the edge of what the relief resolves (it is band-limited below 4 cells a column).
constexpr double kBrushFlowBatchCells = 4.0;

// The squeeze is a diffusion of paint down the head's pressure. Its explicit pass moves at
// most an eighth of the pressure difference across a face (to stay stable), so a furrow of a
// given width in mm, spanning more cells on a finer grid, evens out at a rate per pass that
// falls as the cell's square while the passes per mm rise only as the cell: on a fine grid
// the squeeze fell behind and the bristles' furrows faded with the dpi, on a coarse one it ran
// ahead. A step (a cell travelled) makes kReferenceCellMm / cell_mm passes' worth of
// squeeze, in whole passes each saturating at its share (Stepper::squeeze_passes), so the
// squeeze per mm travelled is the same on every grid: one full pass at 254 dpi.

constexpr std::size_t kBaseCacheTiles = 256;

// Sets the one-cell border of a padded grid to zero.
void zero_border(float* grid, int width, int height) {
  const int stride = width + 2;
  std::fill(grid, grid + stride, 0.0f);
  float* last = grid + static_cast<std::ptrdiff_t>(height + 1) * stride;
  std::fill(last, last + stride, 0.0f);
  for (int y = 1; y <= height; ++y) {
    grid[static_cast<std::ptrdiff_t>(y) * stride] = 0.0f;
    grid[static_cast<std::ptrdiff_t>(y) * stride + width + 1] = 0.0f;
  }
}

IMPASTO_SIMD_CLONES void clamp_at_zero(float* __restrict amount, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) amount[i] = greater(amount[i], 0.0f);
}

// The level the brush's paint fills the ground's valleys to: the mean ground and dry paint
// over about two repeats of the plain weave (2.5 mm) around the brush's centre. Over the few
// cells the tip rests on, the mean rose and fell with the weave as the brush moved, and the
// trailing edge printed that into every cell it left.
double footing_mm(const Canvas& canvas, int cx, int cy) {
  const int half =
      std::max(1, static_cast<int>(std::lround(2.0 * kWeaveThreadPitchMm / canvas.cell_mm())));
  const int x0 = std::clamp(cx - half, 0, canvas.width_cells() - 1);
  const int x1 = std::clamp(cx + half, 0, canvas.width_cells() - 1);
  const int y0 = std::clamp(cy - half, 0, canvas.height_cells() - 1);
  const int y1 = std::clamp(cy + half, 0, canvas.height_cells() - 1);
  double sum = 0.0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      sum += static_cast<double>(canvas.base_height_mm(x, y)) + canvas.dry_height_mm(x, y);
  return sum / (static_cast<double>(x1 - x0 + 1) * (y1 - y0 + 1));
}

}  // namespace

void Stepper::resize(int slot_count, std::size_t brush_cells, int substeps, int squeeze_passes) {
  const Window& w = win_;
  const std::size_t n = w.padded();
  const std::size_t cells = static_cast<std::size_t>(w.width) * w.height;
  const std::size_t slots = static_cast<std::size_t>(slot_count);
  for (auto* grid : {&ground_, &wet_, &pen_, &vx_, &vy_, &new_wet_})
    if (grid->size() < n) grid->resize(n);
  if (pigment_.size() < n * slots) pigment_.resize(n * slots);
  if (new_pigment_.size() < n * slots) new_pigment_.resize(n * slots);
  if (brush_cell_.size() < cells) brush_cell_.resize(cells);
  if (brush_paint_at_.size() < cells) brush_paint_at_.resize(cells);
  if (brush_share_cap_.size() < cells) brush_share_cap_.resize(cells);
  if (xfer_.size() < cells) xfer_.resize(cells);
  if (contact_weight_.size() < cells) contact_weight_.resize(cells);
  if (touch_.size() < cells) touch_.resize(cells);
  if (drag_weight_.size() < cells) drag_weight_.resize(cells);
  for (auto* faces : {&face_east_, &face_south_}) {
    if (faces->size() < n) faces->resize(n);
    zero_border(faces->data(), w.width, w.height);
  }
  if (xfer_ratio_.size() < cells) xfer_ratio_.resize(cells);
  if (substeps > 1 && exchanged_.size() < cells) exchanged_.resize(cells);
  if (substeps > 1 || squeeze_passes > 1) {
    for (auto* grid : {&head_level_, &pen_now_})
      if (grid->size() < n) grid->resize(n);
    zero_border(pen_now_.data(), w.width, w.height);
  }
  if (xfer_pigment_.size() < cells * slots) xfer_pigment_.resize(cells * slots);
  if (brush_share_.size() < brush_cells) brush_share_.resize(brush_cells);
  row_contacts_.assign(static_cast<std::size_t>(w.height), 0);
  for (auto* span : {&contact_lo_, &contact_hi_, &span_lo_, &span_hi_, &need_lo_, &need_hi_})
    span->assign(static_cast<std::size_t>(w.height), 0);
  for (auto* grid : {&ground_, &wet_, &pen_, &vx_, &vy_, &new_wet_})
    zero_border(grid->data(), w.width, w.height);
  for (std::size_t s = 0; s < slots; ++s) {
    zero_border(pigment_.data() + s * n, w.width, w.height);
    zero_border(new_pigment_.data() + s * n, w.width, w.height);
  }
}

const float* Stepper::base_heights(const Canvas& canvas, int tile_index) {
  if (const Tile* tile = canvas.tile(tile_index)) return tile->base_height_mm.data();
  auto it = base_cache_.find(tile_index);
  if (it == base_cache_.end()) {
    it = base_cache_.emplace(tile_index, std::vector<float>(kTileCells)).first;
    canvas.compute_base_heights(tile_index, it->second.data());
  }
  return it->second.data();
}

void Stepper::find_bases(const Canvas& canvas) {
  const Window& w = win_;
  tx0_ = w.x0 / kTileSize;
  ty0_ = w.y0 / kTileSize;
  const int tx1 = (w.x0 + w.width - 1) / kTileSize, ty1 = (w.y0 + w.height - 1) / kTileSize;
  tiles_across_ = tx1 - tx0_ + 1;
  // The cache is emptied before a window's tiles are looked up, never while: clearing it
  // midway left the window's first tiles pointing at freed heights (an empty brush swept
  // over 256 unpainted tiles).
  const auto window_tiles = static_cast<std::size_t>(tiles_across_) * (ty1 - ty0_ + 1);
  if (base_cache_.size() + window_tiles > kBaseCacheTiles) base_cache_.clear();
  bases_.clear();
  for (int ty = ty0_; ty <= ty1; ++ty)
    for (int tx = tx0_; tx <= tx1; ++tx)
      bases_.push_back(base_heights(canvas, canvas.tile_index(tx, ty)));
}

IMPASTO_SIMD_CLONES void Stepper::gather_rows(const StepInputs& in, int r0, int r1) {
  const Window& w = win_;
  const std::size_t n = w.padded();
  for (int y = r0; y < r1; ++y) {
    const int cy = w.y0 + y;
    const int ty = cy / kTileSize;
    for (int k = 0; k < tiles_across_; ++k) {
      const int tx = tx0_ + k;
      const int begin = std::max(w.x0, tx * kTileSize);
      const int end = std::min(w.x0 + w.width, (tx + 1) * kTileSize);
      const std::size_t local =
          static_cast<std::size_t>((cy % kTileSize) * kTileSize + begin - tx * kTileSize);
      const std::size_t dst =
          static_cast<std::size_t>(y + 1) * w.stride() + static_cast<std::size_t>(begin - w.x0 + 1);
      const std::size_t len = static_cast<std::size_t>(end - begin);
      const float* base = bases_[static_cast<std::size_t>((ty - ty0_) * tiles_across_ + k)] + local;
      const Tile* tile = in.canvas->tile(tx, ty);
      if (tile) {
        const float* dry = tile->dry_height_mm.data() + local;
        for (std::size_t i = 0; i < len; ++i) ground_[dst + i] = base[i] + dry[i];
        std::copy_n(tile->wet_volume_mm.data() + local, len, wet_.data() + dst);
      } else {
        std::copy_n(base, len, ground_.data() + dst);
        std::fill_n(wet_.data() + dst, len, 0.0f);
      }
      for (int s = 0; s < in.slot_count; ++s) {
        float* out = pigment_.data() + static_cast<std::size_t>(s) * n + dst;
        const float* from = tile ? tile->pigment(s) : nullptr;
        if (from)
          std::copy_n(from + local, len, out);
        else
          std::fill_n(out, len, 0.0f);
      }
    }
  }
}

void Stepper::penetrate_rows(const StepInputs& in, int r0, int r1) {
  const Window& w = win_;
  HeadRow head{in.brush->padded_coverage().data(), in.brush->padded_footprint_mm().data(),
               in.brush->volume_mm().data(), in.brush->cells_across()};
  // Brush coordinates are affine in x: from the row's first cell centre, in steps.
  head.step_u = static_cast<float>(in.placement.to_brush[0]);
  head.step_v = static_cast<float>(in.placement.to_brush[2]);
  head.tip_mm = in.tip_mm;
  head.footing_mm = in.footing_mm;
  head.ground_fill = in.ground_fill;
  head.inv_touch_mm = in.inv_touch_mm;
  head.surface_mm = in.surface_mm;
  head.coverage_transposed = in.brush->padded_coverage_transposed().data();
  head.footprint_transposed = in.brush->padded_footprint_mm_transposed().data();
  // A head square to the canvas rows, to a thousandth of a cell across the window (a head
  // settled on the travel's heading), takes the aligned kernel, at the row's middle: the
  // bilinear weights change by less than that.
  const double drift_v = std::abs(in.placement.to_brush[2]) * w.width;
  const double drift_u = std::abs(in.placement.to_brush[0]) * w.width;
  const bool along_u = drift_v <= 1e-3, along_v = !along_u && drift_u <= 1e-3;
  for (int y = r0; y < r1; ++y) {
    double bx, by;
    in.placement.brush_coords(w.x0 + 0.5, w.y0 + y + 0.5, bx, by);
    const double middle = 0.5 * w.width;
    head.u0 = static_cast<float>(bx + 0.5 + (along_v ? in.placement.to_brush[0] * middle : 0.0));
    head.v0 = static_cast<float>(by + 0.5 + (along_u ? in.placement.to_brush[2] * middle : 0.0));
    const std::size_t row = static_cast<std::size_t>(y + 1) * w.stride() + 1;
    const std::size_t first = static_cast<std::size_t>(y) * w.width;
    float* pen = pen_.data() + row;
    const float* ground = ground_.data() + row;
    const float* wet = wet_.data() + row;
    std::int32_t* cell = brush_cell_.data() + first;
    float* weight = contact_weight_.data() + first;
    float* on_brush = brush_paint_at_.data() + first;
    float* touch = touch_.data() + first;
    if (along_u || along_v) {
      row_contacts_[static_cast<std::size_t>(y)] = penetrate_aligned_row(
          w.width, head, along_v, ground, wet, pen, cell, weight, on_brush, touch);
    } else {
      // A turned head's grid crosses only part of the row (its window is the grid's bounding
      // box): the kernel visits that part, the rest has no contact.
      int begin, end;
      head_span(w.width, head, begin, end);
      clear_contact(0, begin, pen, cell, weight, on_brush, touch);
      clear_contact(end, w.width, pen, cell, weight, on_brush, touch);
      row_contacts_[static_cast<std::size_t>(y)] =
          penetrate_row(begin, end, head, ground, wet, pen, cell, weight, on_brush, touch);
    }
    // The row's touching cells lie in [first, last + 1).
    int first_touch = w.width, last_touch = -1;
    if (row_contacts_[static_cast<std::size_t>(y)] > 0) {
      first_touch = 0;
      while (cell[first_touch] < 0) ++first_touch;
      last_touch = w.width - 1;
      while (cell[last_touch] < 0) --last_touch;
    }
    contact_lo_[static_cast<std::size_t>(y)] = first_touch;
    contact_hi_[static_cast<std::size_t>(y)] = last_touch + 1;
  }
}

namespace {

// Cells beyond the canvas do not exist: paint at the edge cannot leave. Zeroes the velocity of
// window row `y` (vx, vy) where it points off the canvas, whose last cells are last_x, last_y.
template <typename Window>
void keep_paint_on_canvas(const Window& w, int y, int last_x, int last_y, float* vx, float* vy) {
  if (w.x0 == 0) vx[0] = std::max(vx[0], 0.0f);
  if (w.x0 + w.width - 1 == last_x) vx[w.width - 1] = std::min(vx[w.width - 1], 0.0f);
  if (w.y0 + y == 0)
    for (int x = 0; x < w.width; ++x) vy[x] = std::max(vy[x], 0.0f);
  if (w.y0 + y == last_y)
    for (int x = 0; x < w.width; ++x) vy[x] = std::min(vy[x], 0.0f);
}

}  // namespace

IMPASTO_SIMD_CLONES void Stepper::velocity_rows(const StepInputs& in, int r0, int r1) {
  const Window& w = win_;
  const std::ptrdiff_t s = w.stride();
  const int last_x = in.canvas->width_cells() - 1, last_y = in.canvas->height_cells() - 1;
  for (int y = r0; y < r1; ++y) {
    const std::ptrdiff_t row = (y + 1) * s + 1;
    const float* __restrict weight = (in.blade ? drag_weight_ : contact_weight_).data() +
                                     static_cast<std::ptrdiff_t>(y) * w.width;
    float* __restrict vx = vx_.data() + row;
    float* __restrict vy = vy_.data() + row;
    // v = drag * brush motion under the head, weighted by how fully it covers the cell
    // (branch-free: vectorises). The squeeze is a separate pass (squeeze_rows).
    for (int x = 0; x < w.width; ++x) {
      vx[x] = weight[x] * in.brush_vx;
      vy[x] = weight[x] * in.brush_vy;
    }
    keep_paint_on_canvas(w, y, last_x, last_y, vx, vy);
  }
}

IMPASTO_SIMD_CLONES void Stepper::shifted_velocity_rows(const StepInputs& in, int shift_x,
                                                        int shift_y, float brush_vx, float brush_vy,
                                                        int r0, int r1) {
  // velocity_rows with the contact where it was shift cells back along the move: cell
  // (x, y) moves as the step's cell (x + shift_x, y + shift_y) does.
  const Window& w = win_;
  const std::ptrdiff_t s = w.stride();
  const int last_x = in.canvas->width_cells() - 1, last_y = in.canvas->height_cells() - 1;
  // Only the cells a sub-step's gather reads (need_lo_, need_hi_): elsewhere the velocity is
  // never used.
  for (int y = r0; y < r1; ++y) {
    const int lo = need_lo_[static_cast<std::size_t>(y)],
              hi = need_hi_[static_cast<std::size_t>(y)];
    if (hi <= lo) continue;
    const std::ptrdiff_t row = (y + 1) * s + 1;
    float* __restrict vx = vx_.data() + row;
    float* __restrict vy = vy_.data() + row;
    std::fill(vx + lo, vx + hi, 0.0f);
    std::fill(vy + lo, vy + hi, 0.0f);
    const int from_y = y + shift_y;
    if (from_y < 0 || from_y >= w.height) continue;
    const float* __restrict weight = (in.blade ? drag_weight_ : contact_weight_).data() +
                                     static_cast<std::ptrdiff_t>(from_y) * w.width + shift_x;
    const int begin = std::clamp(-shift_x, lo, hi), end = std::clamp(w.width - shift_x, lo, hi);
    for (int x = begin; x < end; ++x) {
      vx[x] = weight[x] * brush_vx;
      vy[x] = weight[x] * brush_vy;
    }
    keep_paint_on_canvas(w, y, last_x, last_y, vx, vy);
  }
}

void Stepper::blade_drag_rows(double move_x, double move_y, float drag, int r0, int r1) {
  // A blade is rigid: at its leading edge (a touching cell whose neighbour ahead it does not
  // touch) it pushes all the paint above its underside ahead of it, and under it the paint
  // moves as under bristles (drag times the contact). So an empty knife drawn flat through
  // wet paint scrapes it down to a film and drives it ahead into a ridge, and a loaded one
  // lays its paint behind it without pushing that on too. (Dragged by a fifth of its
  // motion everywhere, the knife planed wet paint into a raised slab.)
  const Window& w = win_;
  const double length = std::hypot(move_x, move_y);
  const int ax = length > 0.0 ? static_cast<int>(std::lround(move_x / length)) : 0;
  const int ay = length > 0.0 ? static_cast<int>(std::lround(move_y / length)) : 0;
  const std::ptrdiff_t s = w.stride();
  for (int y = r0; y < r1; ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * w.width;
    for (int x = 0; x < w.width; ++x) {
      const std::size_t c = first + static_cast<std::size_t>(x);
      drag_weight_[c] = drag * contact_weight_[c];
      if (brush_cell_[c] < 0 || (ax == 0 && ay == 0)) continue;
      const int fx = x + ax, fy = y + ay;
      const bool ahead_touches =
          fx >= 0 && fx < w.width && fy >= 0 && fy < w.height &&
          brush_cell_[static_cast<std::size_t>(fy) * w.width + static_cast<std::size_t>(fx)] >= 0;
      if (ahead_touches) continue;
      const auto padded = static_cast<std::size_t>((y + 1) * s + 1 + x);
      const float wet = wet_[padded];
      drag_weight_[c] = wet > 0.0f ? std::min(pen_[padded] / wet, 1.0f) : 0.0f;
    }
  }
}

void Stepper::need_shares(int rows, int cols, int quadrant_x, int quadrant_y) {
  // The gather of a span cell (x, y) reads the shares of (x, y), of the cell behind it across
  // x, and of the row behind it (y - quadrant_y) at those two columns: a row's own span and
  // the span of the row ahead of it, each widened by the cell behind.
  for (int y = 0; y < rows; ++y) {
    int lo = cols, hi = 0;
    for (const int reader : {y, y + quadrant_y}) {
      if (reader < 0 || reader >= rows) continue;
      const auto k = static_cast<std::size_t>(reader);
      if (span_hi_[k] <= span_lo_[k]) continue;
      lo = std::min(lo, span_lo_[k] - std::max(quadrant_x, 0));
      hi = std::max(hi, span_hi_[k] + std::max(-quadrant_x, 0));
    }
    need_lo_[static_cast<std::size_t>(y)] = std::clamp(lo, 0, cols);
    need_hi_[static_cast<std::size_t>(y)] = std::clamp(hi, 0, cols);
  }
}

void Stepper::transfer_rows(const StepInputs& in, int r0, int r1) {
  const Window& w = win_;
  const std::size_t n = w.padded();
  const std::size_t cells = static_cast<std::size_t>(w.width) * w.height;
  const FilmSplit split{in.tip_film_mm, in.relax, in.deposit_share, in.ground_fill, in.footing_mm};
  const float* brush_pigment = in.brush->pigment_mm().data();
  const std::size_t brush_cells = in.brush->cell_count();
  for (int y = r0; y < r1; ++y) {
    // Only the row's active span: elsewhere nothing touches (see step).
    const int lo = span_lo_[static_cast<std::size_t>(y)],
              hi = span_hi_[static_cast<std::size_t>(y)];
    if (hi <= lo) continue;
    const std::size_t row = static_cast<std::size_t>(y + 1) * w.stride() + 1 + lo;
    const std::size_t first = static_cast<std::size_t>(y) * w.width + lo;
    transfer_row(hi - lo, split, brush_cell_.data() + first, brush_paint_at_.data() + first,
                 // (Where the cap cannot bind the brush paint stands in: no extra stream.)
                 (in.sharing_binds ? brush_share_cap_.data() : brush_paint_at_.data()) + first,
                 touch_.data() + first, pen_.data() + row, ground_.data() + row, wet_.data() + row,
                 new_wet_.data() + row, xfer_.data() + first, xfer_ratio_.data() + first);
    for (int s = 0; s < in.slot_count; ++s) {
      const std::size_t k = static_cast<std::size_t>(s);
      // (The brush changes only in the next pass: its pigments are read here directly.)
      transfer_pigment_row(hi - lo, brush_cell_.data() + first, xfer_.data() + first,
                           xfer_ratio_.data() + first, brush_pigment + k * brush_cells,
                           new_pigment_.data() + k * n + row,
                           xfer_pigment_.data() + k * cells + first);
    }
  }
}

bool Stepper::shifted_span(int y, Shift shift, int& lo, int& hi) const {
  // Row y's active span, where a sub-step's contact (the step's, shifted) can lie: the cells
  // whose shifted cell is in the window. False when none is.
  lo = std::max(span_lo_[static_cast<std::size_t>(y)], -shift.x);
  hi = std::min(span_hi_[static_cast<std::size_t>(y)], win_.width - shift.x);
  return hi > lo && y + shift.y >= 0 && y + shift.y < win_.height;
}

void Stepper::shifted_transfer_rows(const StepInputs& in, Shift shift, float relax,
                                    const float* wet, float* new_wet, float* new_pigment, int r0,
                                    int r1) {
  // transfer_rows for one sub-step of a long step: the head where it was then, which is the
  // step's own contact shifted back along the move (cell (x, y) meets the brush cell that the
  // step's cell (x + shift.x, y + shift.y) does), with the brush's paint as the sub-steps
  // before left it. `wet` is the sub-step's input, new_wet and new_pigment its output.
  const Window& w = win_;
  const std::size_t n = w.padded();
  const std::size_t cells = static_cast<std::size_t>(w.width) * w.height;
  const FilmSplit split{in.tip_film_mm, relax, in.deposit_share, in.ground_fill, in.footing_mm};
  const float* brush_volume = in.brush->volume_mm().data();
  const float* brush_pigment = in.brush->pigment_mm().data();
  const std::size_t brush_cells = in.brush->cell_count();
  thread_local std::vector<float> on_brush, cap;
  if (on_brush.size() < static_cast<std::size_t>(w.width)) {
    on_brush.resize(static_cast<std::size_t>(w.width));
    cap.resize(static_cast<std::size_t>(w.width));
  }
  for (int y = r0; y < r1; ++y) {
    const int from_y = y + shift.y;
    const std::size_t first = static_cast<std::size_t>(y) * w.width;
    // Cells of the span beyond the shifted contact exchange nothing.
    const int a = span_lo_[static_cast<std::size_t>(y)], b = span_hi_[static_cast<std::size_t>(y)];
    if (b > a)
      std::fill(xfer_.begin() + static_cast<std::ptrdiff_t>(first + a),
                xfer_.begin() + static_cast<std::ptrdiff_t>(first + b), 0.0f);
    int lo, hi;
    if (!shifted_span(y, shift, lo, hi)) continue;
    const std::size_t from_first =
        static_cast<std::size_t>(from_y) * w.width + static_cast<std::size_t>(lo + shift.x);
    const std::int32_t* cell = brush_cell_.data() + from_first;
    const int count = hi - lo;
    for (int x = 0; x < count; ++x) {
      const std::int32_t b = cell[x];
      // (Clamped once a step: a sub-step's float rounding may leave a hair below 0.)
      on_brush[static_cast<std::size_t>(x)] = b >= 0 ? std::max(brush_volume[b], 0.0f) : 0.0f;
      const std::int32_t sharing =
          b >= 0 && in.sharing_binds ? brush_share_[static_cast<std::size_t>(b)] : 1;
      cap[static_cast<std::size_t>(x)] = sharing <= 1 ? on_brush[static_cast<std::size_t>(x)]
                                                      : on_brush[static_cast<std::size_t>(x)] *
                                                            in.inv_deposit_share /
                                                            static_cast<float>(sharing);
    }
    const std::size_t row = static_cast<std::size_t>(y + 1) * w.stride() + 1 + lo;
    const std::size_t from_row = static_cast<std::size_t>(from_y + 1) * w.stride() + 1 +
                                 static_cast<std::size_t>(lo + shift.x);
    transfer_row(count, split, cell, on_brush.data(), cap.data(), touch_.data() + from_first,
                 pen_.data() + from_row, ground_.data() + row, wet + row, new_wet + row,
                 xfer_.data() + first + lo, xfer_ratio_.data() + first + lo);
    for (int s = 0; s < in.slot_count; ++s) {
      const std::size_t k = static_cast<std::size_t>(s);
      transfer_pigment_row(count, cell, xfer_.data() + first + lo, xfer_ratio_.data() + first + lo,
                           brush_pigment + k * brush_cells, new_pigment + k * n + row,
                           xfer_pigment_.data() + k * cells + first + lo);
    }
    for (int x = a; x < b; ++x)
      exchanged_[first + static_cast<std::size_t>(x)] += xfer_[first + static_cast<std::size_t>(x)];
  }
}

void Stepper::shifted_transfer_to_brush(Brush& brush, int slot_count, Shift shift, int r0, int r1) {
  // transfer_to_brush for a sub-step: the brush cells of the shifted contact.
  const Window& w = win_;
  const std::size_t cells = static_cast<std::size_t>(w.width) * w.height;
  const std::size_t brush_cells = brush.cell_count();
  float* volume = brush.volume_mm().data();
  float* pigment = brush.pigment_mm().data();
  for (int y = r0; y < r1; ++y) {
    int lo, hi;
    if (!shifted_span(y, shift, lo, hi)) continue;
    const std::size_t first = static_cast<std::size_t>(y) * w.width;
    const std::int32_t* cell =
        brush_cell_.data() + static_cast<std::size_t>(y + shift.y) * w.width + shift.x;
    for (int x = lo; x < hi; ++x) {
      if (cell[x] < 0) continue;
      const auto bc = static_cast<std::size_t>(cell[x]);
      const std::size_t c = first + static_cast<std::size_t>(x);
      volume[bc] -= xfer_[c];
      for (std::size_t k = 0; k < static_cast<std::size_t>(slot_count); ++k)
        pigment[k * brush_cells + bc] -= xfer_pigment_[k * cells + c];
    }
  }
}

IMPASTO_SIMD_CLONES void Stepper::squeeze_rows(const float* pen_grid, Shift shift, float c,
                                               float reach, int r0, int r1) {
  // The squeeze: paint flows across each face between cells, from the side the head presses
  // deeper to the other, flux = h v with v = 2 c dp per face. Faces, not cell velocities: a
  // cell-centred gradient cannot see a checkerboard, which then grew under a still brush.
  // Saturated at `reach` (at most 1) times an eighth of the penetration difference and at a
  // quarter of the source's paint per face, so four faces together never overshoot or take
  // more than a cell holds.
  // pen_grid: how deep the head presses each cell; its contact (how fully it moves the
  // paint) is the step's shifted by `shift` (a long step's sub-step: see
  // shifted_transfer_rows). (Branch-free, and faces on padded grids whose border stays 0:
  // the loops vectorise.)
  const Window& w = win_;
  const std::ptrdiff_t s = w.stride();
  // The signed share of the source's paint that crosses (> 0: from this cell).
  const float saturation = 16.0f / reach;
  const auto share = [c, saturation](float dp, float h_from, float h_to, float contact) {
    // (A hair below 0 from float rounding moves nothing: divided by the 1e-30 floor, it blew up.)
    const float h = std::max(dp > 0.0f ? h_from : h_to, 0.0f);
    const float flux =
        std::min(2.0f * c * h * std::abs(dp) / (1.0f + saturation * c * h), 0.25f * h);
    const float ratio = contact * flux / std::max(h, 1e-30f);
    return dp > 0.0f ? ratio : -ratio;
  };
  // Cells whose shifted contact lies in the window: [lo, hi). A long step's sub-steps
  // compute only each row's face range (face_lo_, face_hi_: zeroed once a step, and no face
  // beyond it can carry paint); a one-cell step computes the whole row.
  const int lo = std::max(0, -shift.x), hi = std::min(w.width, w.width - shift.x);
  for (int y = r0; y < r1; ++y) {
    const std::ptrdiff_t row = (y + 1) * s + 1;
    float* __restrict east = face_east_.data() + row;
    float* __restrict south = face_south_.data() + row;
    const int from_y = y + shift.y;
    const int range_lo = faces_in_range_ ? face_lo_[static_cast<std::size_t>(y)] : 0;
    const int range_hi = faces_in_range_ ? face_hi_[static_cast<std::size_t>(y)] : w.width;
    if (range_hi <= range_lo) continue;
    const int a = std::max(lo, range_lo), b = std::min(hi, range_hi);
    std::fill(east + range_lo, east + range_hi, 0.0f);
    std::fill(south + range_lo, south + range_hi, 0.0f);
    if (from_y < 0 || from_y >= w.height || b <= a) continue;
    const std::size_t first = static_cast<std::size_t>(from_y) * w.width;
    const float* __restrict pen = pen_grid + row;
    const float* __restrict wet = new_wet_.data() + row;
    const float* __restrict weight = contact_weight_.data() + first + shift.x;
    const int east_end = std::min(b, hi - 1);  // the window's edge: no face
    for (int x = a; x < east_end; ++x)
      east[x] = share(pen[x] - pen[x + 1], wet[x], wet[x + 1], std::max(weight[x], weight[x + 1]));
    if (y + 1 < w.height && from_y + 1 < w.height) {
      const float* __restrict below = weight + w.width;
      for (int x = a; x < b; ++x)
        south[x] = share(pen[x] - pen[x + s], wet[x], wet[x + s], std::max(weight[x], below[x]));
    }
  }
}

Stepper::SqueezePasses Stepper::squeeze_passes(double cell_mm) {
  const double passes_wanted = kReferenceCellMm / cell_mm;
  const int passes = std::max(1, static_cast<int>(std::ceil(passes_wanted - 1e-9)));
  return {passes, static_cast<float>(std::min(passes_wanted / passes, 1.0))};
}

void Stepper::squeeze_in_passes(Shift shift, float level_offset_mm, float c, SqueezePasses plan,
                                int slot_count) {
  // The squeeze of a step (or sub-step) in plan.passes passes of c / passes each: all but the
  // last are applied here (the step's result back into its input grids, then copied on as
  // the next pass's input, the head's pressure measured again on the paint as moved); the
  // last pass's faces are left for the caller to apply, as one pass's are.
  const Window& w = win_;
  const int rows = w.height, cols = w.width;
  const float per_pass = c / static_cast<float>(plan.passes);
  const std::size_t n = w.padded();
  // (The first pass measures the step's own pressure: a sub-step's, or a short step's.)
  const float* pen = swept_ ? pen_now_.data() : pen_.data();
  for (int pass = 1; pass < plan.passes; ++pass) {
    parallel_rows(rows, cols,
                  [&](int r0, int r1) { squeeze_rows(pen, shift, per_pass, plan.reach, r0, r1); });
    // (Applied in full before any row is copied on: a row's pass reads its neighbours' input.)
    parallel_rows(rows, cols, [&](int r0, int r1) { apply_squeeze_rows(slot_count, r0, r1); });
    parallel_rows(rows, cols, [&](int r0, int r1) {
      for (int y = r0; y < r1; ++y) {
        const int lo = span_lo_[static_cast<std::size_t>(y)];
        const int hi = span_hi_[static_cast<std::size_t>(y)];
        if (hi <= lo) continue;
        const std::size_t row = static_cast<std::size_t>(y + 1) * w.stride() + 1;
        for (int k = 0; k <= slot_count; ++k) {
          const std::size_t plane = k == 0 ? 0 : static_cast<std::size_t>(k - 1) * n;
          const float* from = (k == 0 ? wet_.data() : pigment_.data() + plane) + row;
          float* to = (k == 0 ? new_wet_.data() : new_pigment_.data() + plane) + row;
          std::copy(from + lo, from + hi, to + lo);
        }
      }
    });
    parallel_rows(rows, cols, [&](int r0, int r1) {
      sub_step_penetration_rows(shift, level_offset_mm, r0, r1);
    });
    pen = pen_now_.data();
  }
  parallel_rows(rows, cols,
                [&](int r0, int r1) { squeeze_rows(pen, shift, per_pass, plan.reach, r0, r1); });
}

void Stepper::sub_step_penetration_rows(Shift shift, float level_offset_mm, int r0, int r1) {
  // How deep the head presses each cell in a long step's sub-step: its underside where the
  // step's contact, shifted, puts it (head_level_), against the paint as the sub-step has
  // left it, raised by level_offset_mm (a pen pressing less as the step went on, or a brush
  // lifting, was deeper earlier in the step). The step's own penetration, shifted, would not
  // see the paint the squeeze moves: pressed from where it had been, the paint overshot into a
  // ripple across the stroke; and a lifting brush held at each step's depth left a ring where
  // each step's footprint stopped pressing.
  const Window& w = win_;
  const std::ptrdiff_t s = w.stride();
  for (int y = r0; y < r1; ++y) {
    const std::ptrdiff_t row = (y + 1) * s + 1;
    float* pen = pen_now_.data() + row;
    std::fill_n(pen, w.width, 0.0f);
    int lo, hi;
    if (!shifted_span(y, shift, lo, hi)) continue;
    const int from_y = y + shift.y;
    const std::ptrdiff_t from_row = (from_y + 1) * s + 1 + shift.x;
    const std::int32_t* cell =
        brush_cell_.data() + static_cast<std::size_t>(from_y) * w.width + shift.x;
    const float* level = head_level_.data() + from_row;
    const float* ground = ground_.data() + row;
    const float* wet = new_wet_.data() + row;
    for (int x = lo; x < hi; ++x)
      pen[x] =
          cell[x] >= 0 ? std::max(ground[x] + wet[x] - (level[x] + level_offset_mm), 0.0f) : 0.0f;
  }
}

IMPASTO_SIMD_CLONES void Stepper::apply_squeeze_rows(int slot_count, int r0, int r1) {
  // Every quantity moves with the faces' shares of its source: what one cell gives, its
  // neighbour gets, computed from the same product (paint and pigments alike). Each face
  // adds its two terms, one of them exactly 0 (branch-free: the loop vectorises).
  const Window& w = win_;
  const std::ptrdiff_t s = w.stride();
  const std::size_t n = w.padded();
  for (int k = 0; k <= slot_count; ++k) {
    const float* q =
        k == 0 ? new_wet_.data() : new_pigment_.data() + static_cast<std::size_t>(k - 1) * n;
    float* out = k == 0 ? wet_.data() : pigment_.data() + static_cast<std::size_t>(k - 1) * n;
    for (int y = r0; y < r1; ++y) {
      // Only the row's active span: elsewhere every face is 0 and out already equals q.
      const int lo = span_lo_[static_cast<std::size_t>(y)];
      const int hi = span_hi_[static_cast<std::size_t>(y)];
      const std::ptrdiff_t row = (y + 1) * s + 1;
      const float* __restrict e = face_east_.data() + row;    // e[-1]: the west face
      const float* __restrict so = face_south_.data() + row;  // so[-s]: the north face
      const float* __restrict c = q + row;
      float* __restrict o = out + row;
      for (int x = lo; x < hi; ++x) {
        const float ee = e[x], ew = e[x - 1], es = so[x], en = so[x - s];
        float value = c[x];
        value += -(std::max(ee, 0.0f) * c[x]) - std::min(ee, 0.0f) * c[x + 1];
        value += std::max(ew, 0.0f) * c[x - 1] + std::min(ew, 0.0f) * c[x];
        value += -(std::max(es, 0.0f) * c[x]) - std::min(es, 0.0f) * c[x + s];
        value += std::max(en, 0.0f) * c[x - s] + std::min(en, 0.0f) * c[x];
        o[x] = value;
      }
    }
  }
}

void Stepper::share_brush_cells(std::size_t cells, float inv_deposit_share) {
  // Counts the canvas cells touching each brush cell, then caps each one's deposit so that
  // together they never take more than their brush cell holds.
  std::fill(brush_share_.begin(), brush_share_.end(), 0);
  for (std::size_t c = 0; c < cells; ++c)
    if (brush_cell_[c] >= 0) ++brush_share_[static_cast<std::size_t>(brush_cell_[c])];
  for (std::size_t c = 0; c < cells; ++c) {
    const std::int32_t b = brush_cell_[c];
    const std::int32_t sharing = b >= 0 ? brush_share_[static_cast<std::size_t>(b)] : 1;
    brush_share_cap_[c] =
        sharing == 1 ? brush_paint_at_[c]
                     : brush_paint_at_[c] * inv_deposit_share / static_cast<float>(sharing);
  }
}

void Stepper::transfer_to_brush(Brush& brush, int slot_count, int r0, int r1) {
  // In canvas order: exactly what each canvas cell gained, its brush cell lost. Only the
  // rows' touching cells; no clamp here (clamp_brush follows, once per brush cell).
  const std::size_t cells = static_cast<std::size_t>(win_.width) * win_.height;
  const std::size_t brush_cells = brush.cell_count();
  float* volume = brush.volume_mm().data();
  float* pigment = brush.pigment_mm().data();
  const std::int32_t* brush_cell = brush_cell_.data();
  const float* xfer = xfer_.data();
  const float* xfer_pigment = xfer_pigment_.data();
  for (int y = r0; y < r1; ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * win_.width;
    const auto lo = static_cast<std::size_t>(contact_lo_[static_cast<std::size_t>(y)]);
    const auto hi = static_cast<std::size_t>(contact_hi_[static_cast<std::size_t>(y)]);
    for (std::size_t c = first + lo; c < first + hi; ++c) {
      if (brush_cell[c] < 0) continue;  // a gap between touching cells
      const auto bc = static_cast<std::size_t>(brush_cell[c]);
      volume[bc] -= xfer[c];
      for (std::size_t k = 0; k < static_cast<std::size_t>(slot_count); ++k)
        pigment[k * brush_cells + bc] -= xfer_pigment[k * cells + c];
    }
  }
}

void Stepper::clamp_brush(Brush& brush, int slot_count) {
  // Never below zero: a painting file refuses negative paint. The deposit's bound keeps each
  // brush cell a hair above; this only guards the last float rounding.
  clamp_at_zero(brush.volume_mm().data(), brush.cell_count());
  clamp_at_zero(brush.pigment_mm().data(),
                brush.cell_count() * static_cast<std::size_t>(slot_count));
}

void Stepper::even_out_brush(Brush& brush, int slot_count, double share) {
  // Paint flows along the hairs and between the hairs of one bristle, not from bristle to
  // bristle: each covered cell moves `share` of the way to the mean of its column of bristles
  // (the head's +v axis runs along the travel, so a column is what one bristle lays; it spans
  // the cells of Brush::bristle_of_cell_column). Evened out over the whole brush, every
  // bristle held the same paint to the end and a running-dry stroke faded evenly through the
  // weave instead of breaking into streaks where bristles ran dry. Evened out along each
  // column of cells alone, the streaks followed the grid: a splayed head meets some of its
  // cell columns with two canvas cells and some with one, and those ran dry first in a stripe
  // every few cells (5.8 for a fan at any dpi) that read as furrows. Each column's float
  // total is kept exactly: what rounding added or lost goes back into its fullest cell (the
  // first of the fullest, in index order). The sums run in index order, so their bits are
  // fixed. A blade (a head without bristles) is one plate: its paint spreads across it
  // freely, one column the width of the grid.
  const std::size_t cells = brush.cell_count();
  const auto across = static_cast<std::size_t>(brush.cells_across());
  const std::size_t columns = brush.bristle_columns();
  const std::uint32_t* bristle_of = brush.bristle_of_cell_column().data();
  const std::vector<Brush::CellRun>& runs = brush.covered_runs();
  const auto even_out = [&runs, across, columns, bristle_of, share](float* amount) {
    thread_local std::vector<double> total, after;
    thread_local std::vector<std::size_t> count, fullest;
    total.assign(columns, 0.0);
    after.assign(columns, 0.0);
    count.assign(columns, 0);
    fullest.assign(columns, 0);
    // Walks the covered cells in index order with each one's column (runs may wrap a row).
    const auto each = [&](auto&& visit) {
      for (const auto [begin, end] : runs) {
        std::size_t u = begin % across;
        for (std::size_t c = begin; c < end; ++c) {
          visit(c, static_cast<std::size_t>(bristle_of[u]));
          if (++u == across) u = 0;
        }
      }
    };
    each([&](std::size_t c, std::size_t u) {
      total[u] += amount[c];
      if (count[u]++ == 0 || amount[c] > amount[fullest[u]]) fullest[u] = c;
    });
    each([&](std::size_t c, std::size_t u) {
      const double mean = total[u] / static_cast<double>(count[u]);
      amount[c] = std::max(0.0f, static_cast<float>(amount[c] + share * (mean - amount[c])));
      after[u] += amount[c];
    });
    for (std::size_t u = 0; u < columns; ++u)
      if (count[u] > 0 && total[u] > 0.0)
        amount[fullest[u]] = static_cast<float>(amount[fullest[u]] + (total[u] - after[u]));
  };
  // Volume and each pigment are independent: one task each.
  tbb::parallel_for(0, slot_count + 1, [&](int k) {
    even_out(k == 0 ? brush.volume_mm().data()
                    : brush.pigment_mm().data() + static_cast<std::size_t>(k - 1) * cells);
  });
}

void Stepper::finish_stroke(Brush& brush, int slot_count, const SimulationParams& params) {
  if (brush_flow_pending_mm_ > 0.0 && !brush.empty())
    even_out_brush(brush, slot_count,
                   -std::expm1(-brush_flow_pending_mm_ / params.brush_flow_length_mm));
  brush_flow_pending_mm_ = 0.0;
}

double Stepper::max_step_seconds(const SimulationParams& params, double cell_mm) {
  return params.squeeze_mm_s > 0.0 ? 0.5 * cell_mm / params.squeeze_mm_s : 1e300;
}

double Stepper::max_step_cells(const SimulationParams& params, const Brush& brush) {
  return brush.blade() ? 1.0 : paintcore::max_step_cells(params, brush.cells_across());
}

double max_step_cells(const SimulationParams& params, int brush_cells) {
  if (brush_cells < params.long_step_from_cells) return 1.0;
  return std::max(1.0, params.long_step_share * brush_cells);
}

namespace {
// The most steps a pen going from full pressure to none takes for its depth's sake.
constexpr double kMostDepthSteps = 64.0;
}  // namespace

double Stepper::max_step_depth_mm(const SimulationParams& params, const Brush& brush) {
  const double full = brush.max_depth_mm();
  if (!(full > 0.0)) return 1e300;
  double most = params.touch_mm > 0.0 ? 0.5 * params.touch_mm : 1e300;
  // The splay widens the footprint's radius by splay cells_across / 2 at full depth.
  const double splay_cells = 0.5 * brush.head().splay * brush.cells_across();
  if (splay_cells > 0.5) most = std::min(most, 0.5 / splay_cells * full);
  // At most kMostDepthSteps steps from full pressure to none, whatever the fade's depth or
  // the brush's size: a hair-thin fade asked for millions, a 1024-cell brush's splay for
  // hundreds of its costly steps.
  return std::max(most, full / kMostDepthSteps);
}

void Stepper::copy_rows_to_tiles(Canvas& canvas, int slot_count, const float* wet,
                                 const float* pigment, int r0, int r1, int only_tile) const {
  const Window& w = win_;
  const std::size_t n = w.padded();
  const int tx1 = tx0_ + tiles_across_ - 1;
  for (int y = r0; y < r1; ++y) {
    const int cy = w.y0 + y;
    const int ty = cy / kTileSize;
    for (int tx = tx0_; tx <= tx1; ++tx) {
      const int index = canvas.tile_index(tx, ty);
      if (only_tile >= 0 && index != only_tile) continue;
      Tile* tile = canvas.tile_slot(index).get();
      if (!tile) continue;  // (made afterwards if paint arrived, see scatter)
      // A whole new tile's rows, or else only the row's active span (the rest is unchanged).
      const bool whole = only_tile >= 0;
      const int span_lo = whole ? 0 : span_lo_[static_cast<std::size_t>(y)];
      const int span_hi = whole ? w.width : span_hi_[static_cast<std::size_t>(y)];
      const int begin = std::max(w.x0 + span_lo, tx * kTileSize);
      const int end = std::min(w.x0 + span_hi, (tx + 1) * kTileSize);
      if (end <= begin) continue;
      const std::size_t local =
          static_cast<std::size_t>((cy % kTileSize) * kTileSize + begin - tx * kTileSize);
      const std::size_t src =
          static_cast<std::size_t>(y + 1) * w.stride() + static_cast<std::size_t>(begin - w.x0 + 1);
      const std::size_t len = static_cast<std::size_t>(end - begin);
      std::copy_n(wet + src, len, tile->wet_volume_mm.data() + local);
      for (int s = 0; s < slot_count; ++s)
        std::copy_n(pigment + static_cast<std::size_t>(s) * n + src, len, tile->pigment(s) + local);
    }
  }
}

void Stepper::scatter(Canvas& canvas, int slot_count, const BeforeTileChange& before_change,
                      bool squeezes) {
  const Window& w = win_;
  const std::size_t n = w.padded();
  const int tx1 = tx0_ + tiles_across_ - 1;
  const int ty1 = (w.y0 + w.height - 1) / kTileSize;
  // The cells this step can change in existing tiles: the box of the rows' active spans
  // (all that copy_rows_to_tiles writes), so a view re-shades only those.
  CellRect changed{w.x0 + w.width, w.y0 + w.height, w.x0, w.y0};
  for (int y = 0; y < w.height; ++y) {
    const auto k = static_cast<std::size_t>(y);
    if (span_hi_[k] <= span_lo_[k]) continue;
    changed = {std::min(changed.x0, w.x0 + span_lo_[k]), std::min(changed.y0, w.y0 + y),
               std::max(changed.x1, w.x0 + span_hi_[k]), std::max(changed.y1, w.y0 + y + 1)};
  }
  // Tiles that exist are recorded (for undo) and given every slot before the parallel writes.
  missing_tiles_.clear();
  for (int ty = ty0_; ty <= ty1; ++ty)
    for (int tx = tx0_; tx <= tx1; ++tx) {
      const int index = canvas.tile_index(tx, ty);
      if (!canvas.tile(index)) {
        missing_tiles_.push_back(index);
        continue;
      }
      before_change(index);
      canvas.ensure_tile(index, slot_count);
      canvas.mark_dirty(index, changed);
    }
  // The squeeze writes the step's result into the gathered grids, row by row, and each row
  // goes to its tiles at once (one pass); without a squeeze the transfer's grids are it.
  const float* wet = squeezes ? wet_.data() : new_wet_.data();
  const float* pigment = squeezes ? pigment_.data() : new_pigment_.data();
  parallel_rows(w.height, w.width, [&](int r0, int r1) {
    if (squeezes) apply_squeeze_rows(slot_count, r0, r1);
    copy_rows_to_tiles(canvas, slot_count, wet, pigment, r0, r1, -1);
  });
  // A tile that was never painted is made only if paint arrived in it.
  for (const int index : missing_tiles_) {
    const int tx = index % canvas.tiles_x(), ty = index / canvas.tiles_x();
    const int bx0 = std::max(w.x0, tx * kTileSize);
    const int bx1 = std::min(w.x0 + w.width, (tx + 1) * kTileSize);
    const int by0 = std::max(w.y0, ty * kTileSize);
    const int by1 = std::min(w.y0 + w.height, (ty + 1) * kTileSize);
    bool has_paint = false;
    for (int y = by0; y < by1 && !has_paint; ++y)
      for (int x = bx0; x < bx1 && !has_paint; ++x) {
        const std::size_t i = static_cast<std::size_t>(y - w.y0 + 1) * w.stride() + (x - w.x0 + 1);
        has_paint = wet[i] != 0.0f;
        for (int s = 0; s < slot_count && !has_paint; ++s)
          has_paint = pigment[static_cast<std::size_t>(s) * n + i] != 0.0f;
      }
    if (!has_paint) continue;
    before_change(index);
    canvas.ensure_tile(index, slot_count);
    canvas.mark_dirty(index, {bx0, by0, bx1, by1});
    copy_rows_to_tiles(canvas, slot_count, wet, pigment, by0 - w.y0, by1 - w.y0, index);
  }
}

void Stepper::find_active_spans(int rows, int cols) {
  for (int y = 0; y < rows; ++y) {
    int lo = cols, hi = 0;
    for (int near = std::max(y - 1, 0); near <= std::min(y + 1, rows - 1); ++near) {
      const auto k = static_cast<std::size_t>(near);
      if (contact_hi_[k] <= contact_lo_[k]) continue;
      lo = std::min(lo, contact_lo_[k] - 1);
      hi = std::max(hi, contact_hi_[k] + 1);
    }
    // A long step's earlier sub-steps drag where the contact was: shifted back.
    for (const auto [sx, sy] : shifts_)
      for (int near = std::max(y + sy - 1, 0); near <= std::min(y + sy + 1, rows - 1); ++near) {
        const auto k = static_cast<std::size_t>(near);
        if (contact_hi_[k] <= contact_lo_[k]) continue;
        lo = std::min(lo, contact_lo_[k] - sx - 1);
        hi = std::max(hi, contact_hi_[k] - sx + 1);
      }
    span_lo_[static_cast<std::size_t>(y)] = std::clamp(lo, 0, cols);
    span_hi_[static_cast<std::size_t>(y)] = std::clamp(hi, 0, cols);
    if (span_hi_[static_cast<std::size_t>(y)] <= span_lo_[static_cast<std::size_t>(y)])
      span_lo_[static_cast<std::size_t>(y)] = span_hi_[static_cast<std::size_t>(y)] = 0;
  }
}

std::optional<Stepper::StepPlan> Stepper::plan_step(const Canvas& canvas, Brush& brush,
                                                    int slot_count, const SimulationParams& params,
                                                    const BrushPose& pose, double move_x,
                                                    double move_y, double seconds, bool lift_off,
                                                    bool lifting) {
  StepPlan plan;
  // Where the tip was at the last step's end (its depth, as the pen pressed then).
  plan.depth_from = last_depth_mm_.value_or(pose.depth_mm);
  last_depth_mm_ = pose.depth_mm;
  // A pen that does not press (pressure 0) holds the brush off the paint.
  if (brush.empty() || !(pose.depth_mm > 0.0 || lifting)) return std::nullopt;
  brush.ensure_slots(slot_count);
  StepInputs& in = plan.in;
  in.canvas = &canvas;
  in.brush = &brush;
  in.slot_count = slot_count;
  // Bristles splay under pressure: the footprint widens with the depth pressed.
  const double max_depth = brush.max_depth_mm();
  const double pressure = max_depth > 0.0 ? std::clamp(pose.depth_mm / max_depth, 0.0, 1.0) : 0.0;
  in.placement = place_brush(pose, brush.cells_across(), 1.0 + brush.head().splay * pressure);
  // A head without bristles is a blade: rigid, it carries all the paint above its underside
  // (drag 1, contact_rows.cpp); bristles drag a share of what they touch.
  in.blade = brush.blade();
  plan.drag = in.blade ? 1.0 : params.drag;
  const double drag = plan.drag;
  const BrushPlacement& placement = in.placement;
  // The window: the canvas cells the brush grid can cover, plus one cell that advection
  // can push paint into, clipped to the canvas.
  double min_x = placement.centre_x, max_x = min_x, min_y = placement.centre_y, max_y = min_y;
  for (const double bx : {-placement.half_cells, placement.half_cells})
    for (const double by : {-placement.half_cells, placement.half_cells}) {
      const auto& m = placement.to_canvas;
      const double x = placement.centre_x + m[0] * bx + m[1] * by;
      const double y = placement.centre_y + m[2] * bx + m[3] * by;
      min_x = std::min(min_x, x), max_x = std::max(max_x, x);
      min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    }
  const double width = canvas.width_cells(), height = canvas.height_cells();
  const int x0 = static_cast<int>(std::clamp(std::floor(min_x) - 1.0, 0.0, width));
  const int x1 = static_cast<int>(std::clamp(std::ceil(max_x) + 1.0, 0.0, width));
  const int y0 = static_cast<int>(std::clamp(std::floor(min_y) - 1.0, 0.0, height));
  const int y1 = static_cast<int>(std::clamp(std::ceil(max_y) + 1.0, 0.0, height));
  if (x1 <= x0 || y1 <= y0) return std::nullopt;  // the brush is off the canvas
  // A long step (more than a cell) drags the paint in sub-steps of at most
  // long_step_drag_cells travelled, each with the contact where the brush was then (the
  // step's own, shifted back along the move): the drag moves the paint nearly as one-cell
  // steps would, and the contact's trailing edge sweeps the canvas instead of jumping (a jump
  // left a ridge every step). The window reaches back over the cells swept.
  const double travel = std::max(std::abs(move_x), std::abs(move_y));
  plan.substeps = travel > 1.0 + 1e-6
                      ? static_cast<int>(std::ceil(
                            std::max(travel / params.long_step_drag_cells, drag * travel) - 1e-6))
                      : 1;
  const int substeps = plan.substeps;
  shifts_.clear();
  for (int j = 1; j < substeps; ++j) {
    const double back = static_cast<double>(substeps - j) / substeps;
    shifts_.push_back({static_cast<int>(std::lround(back * move_x)),
                       static_cast<int>(std::lround(back * move_y))});
  }
  // What each sub-step moves: from the last position (the step's start, exactly, for the
  // first) to its own, whole cells apart but for the first. The drag, the film split and the
  // squeeze go by these, so the sub-steps of consecutive steps tile the path: with even
  // shares, a step of 12.5 cells split in 13 counted its half-cell first move as a whole one,
  // and pressed a line into the paint every step. Their lengths are scaled to add up to the
  // step's (a staircase is longer than the diagonal it follows).
  sub_moves_.clear();
  {
    double from_x = move_x, from_y = move_y, walked = 0.0;
    for (int j = 1; j <= substeps; ++j) {
      const Shift to = j < substeps ? shifts_[static_cast<std::size_t>(j - 1)] : Shift{0, 0};
      const double dx = from_x - to.x, dy = from_y - to.y;
      sub_moves_.push_back({dx, dy, std::hypot(dx, dy)});
      walked += sub_moves_.back().length;
      from_x = to.x;
      from_y = to.y;
    }
    const double scale = walked > 0.0 ? std::hypot(move_x, move_y) / walked : 0.0;
    for (SubMove& sub : sub_moves_) sub.length *= scale;
  }
  const bool long_step = travel > 1.0 + 1e-6;
  const int back_x = long_step ? static_cast<int>(std::ceil(std::abs(move_x))) : 0;
  const int back_y = long_step ? static_cast<int>(std::ceil(std::abs(move_y))) : 0;
  const int wx0 = move_x > 0.0 ? std::max(x0 - back_x, 0) : x0;
  const int wx1 = move_x < 0.0 ? std::min(x1 + back_x, canvas.width_cells()) : x1;
  const int wy0 = move_y > 0.0 ? std::max(y0 - back_y, 0) : y0;
  const int wy1 = move_y < 0.0 ? std::min(y1 + back_y, canvas.height_cells()) : y1;
  win_ = Window{wx0, wy0, wx1 - wx0, wy1 - wy0};
  plan.squeeze = squeeze_passes(canvas.cell_mm());
  resize(slot_count, brush.cell_count(), substeps, plan.squeeze.passes);
  find_bases(canvas);

  // The tip sinks depth_mm below the surface it rests on: the ground and dry paint, and the
  // share of the wet paint that holds the brush up, averaged around the centre (a surface
  // under one cell would let the brush bob on the paint it has just laid). A blade is rigid:
  // pressed, it cuts through the wet paint toward the ground; held lightly it rides on it.
  const double wet_support = in.blade ? params.wet_support * (1.0 - pressure) : params.wet_support;
  const int reach = std::clamp(brush.cells_across() / 8, 1, 4);
  const int cx = static_cast<int>(std::floor(placement.centre_x));
  const int cy = static_cast<int>(std::floor(placement.centre_y));
  // (And the paint surface there, which the drag's fade measures the head against.)
  double rest = 0.0, surface = 0.0;
  int rest_cells = 0;
  const auto rest_on = [&](int x, int y) {
    const double solid =
        static_cast<double>(canvas.base_height_mm(x, y)) + canvas.dry_height_mm(x, y);
    rest += solid + wet_support * canvas.wet_volume_mm(x, y);
    surface += solid + canvas.wet_volume_mm(x, y);
    ++rest_cells;
  };
  for (int y = std::max(cy - reach, 0); y <= std::min(cy + reach, canvas.height_cells() - 1); ++y)
    for (int x = std::max(cx - reach, 0); x <= std::min(cx + reach, canvas.width_cells() - 1); ++x)
      rest_on(x, y);
  if (rest_cells == 0)  // the centre is off the canvas: rest on the nearest cell
    rest_on(std::clamp(cx, 0, canvas.width_cells() - 1),
            std::clamp(cy, 0, canvas.height_cells() - 1));
  in.footing_mm = static_cast<float>(footing_mm(canvas, cx, cy));
  in.ground_fill = static_cast<float>(params.ground_fill);
  in.inv_touch_mm = params.touch_mm > 0.0 ? static_cast<float>(1.0 / params.touch_mm) : 1e30f;
  // (A blade, rigid, drags all it touches: its drag does not fade.)
  in.surface_mm = in.blade ? 1e30f : static_cast<float>(surface / rest_cells);
  in.tip_mm = static_cast<float>(rest / rest_cells - pose.depth_mm);
  in.brush_vx = static_cast<float>(drag * sub_moves_.back().x);
  in.brush_vy = static_cast<float>(drag * sub_moves_.back().y);
  // The squeeze moves paint down the penetration's slope (mm/mm) by plough mm per mm
  // travelled plus squeeze_mm_s per second: in cells this step, per unit slope, over the
  // central difference's two cells.
  const double cell_mm = canvas.cell_mm();
  plan.distance_mm = std::hypot(move_x, move_y) * cell_mm;
  const double distance_mm = plan.distance_mm;
  const double squeeze_mm = params.plough * distance_mm + params.squeeze_mm_s * seconds;
  in.gradient_scale = static_cast<float>(squeeze_mm / cell_mm * 0.5 / cell_mm);
  in.min_film_mm = static_cast<float>(params.min_film_mm);
  in.relax = static_cast<float>(transfer_relaxation(distance_mm, seconds, params));
  in.deposit_share = static_cast<float>(params.deposit_share);
  in.tip_film_mm = static_cast<float>(params.tip_film_mm);
  if (lift_off) {
    // The brush leaves the paint: the film between the tips still touching (the lift eased
    // the pressure off, Painting::end_stroke) and the canvas breaks in its middle, at once
    // (no motion, no squeeze).
    in.relax = 1.0f;
    in.deposit_share = static_cast<float>(params.lift_share);
  }
  // (With no deposit at all the bound is moot: any finite value above the brush's paint.)
  in.inv_deposit_share = in.deposit_share > 0.0f ? 1.0f / in.deposit_share : 1e30f;
  // A brush cell may touch several canvas cells (a turned, tilted or splayed head): at most
  // as many as its parallelogram's bounding box holds cell centres. Each of k sharers takes
  // at most deposit_share of what the tips present, so the cap of on_brush / k binds only
  // where k * deposit_share > 1 (a lift-off, a steep tilt); only then are sharers counted.
  {
    const auto& m = in.placement.to_canvas;
    const double most_sharing = (std::floor(std::abs(m[0]) + std::abs(m[1])) + 1.0) *
                                (std::floor(std::abs(m[2]) + std::abs(m[3])) + 1.0);
    in.sharing_binds = most_sharing * in.deposit_share > 1.0;
  }
  return plan;
}

bool Stepper::step(Canvas& canvas, Brush& brush, int slot_count, const SimulationParams& params,
                   const BrushPose& pose, double move_x, double move_y, double seconds,
                   const BeforeTileChange& before_change, bool lift_off, bool lifting) {
  last_window_cells_ = 0;
  const std::optional<StepPlan> plan = plan_step(canvas, brush, slot_count, params, pose, move_x,
                                                 move_y, seconds, lift_off, lifting);
  if (!plan) return false;
  const StepInputs& in = plan->in;
  const double drag = plan->drag, depth_from = plan->depth_from;
  const double cell_mm = canvas.cell_mm(), distance_mm = plan->distance_mm;
  const int substeps = plan->substeps;
  const SqueezePasses squeeze = plan->squeeze;

  const int rows = win_.height, cols = win_.width;
  // 1. Gather the window, find where the brush penetrates the paint surface, the velocity
  // and the shares advection will move (each needs only its own row: one pass).
  advection_.resize(cols, rows);
  // (The drag moves every cell's paint the brush's way, or not at all: one quadrant.)
  const int quadrant_x = move_x < 0.0 ? -1 : 1, quadrant_y = move_y < 0.0 ? -1 : 1;
  const auto one_step_shares = [&](int r0, int r1) {
    if (substeps > 1) return;  // each sub-step below has its own velocities and shares
    velocity_rows(in, r0, r1);
    advection_.prepare_quadrant_rows(r0, r1, vx_.data(), vy_.data(), wet_.data(), in.min_film_mm);
  };
  parallel_rows(rows, cols, [&](int r0, int r1) {
    gather_rows(in, r0, r1);
    penetrate_rows(in, r0, r1);
    if (!in.blade) one_step_shares(r0, r1);
  });
  // A blade's leading edge needs the rows around each row's contact: a pass of its own.
  if (in.blade)
    parallel_rows(rows, cols, [&](int r0, int r1) {
      blade_drag_rows(move_x, move_y, static_cast<float>(params.drag), r0, r1);
      one_step_shares(r0, r1);
    });
  int contacts = 0;
  for (const int count : row_contacts_) contacts += count;
  if (contacts == 0) return false;  // nothing touches: nothing changes

  // 2. Advect volume and every active pigment with the same shares, then the transfer.
  const std::size_t cells = static_cast<std::size_t>(cols) * rows;
  from_.assign({wet_.data()});
  to_.assign({new_wet_.data()});
  for (int s = 0; s < slot_count; ++s) {
    from_.push_back(pigment_.data() + static_cast<std::size_t>(s) * win_.padded());
    to_.push_back(new_pigment_.data() + static_cast<std::size_t>(s) * win_.padded());
  }
  const bool transfers = in.relax > 0.0f;  // a brush neither moving nor pressing moves nothing
  last_transferred_ = transfers;
  find_active_spans(rows, cols);
  if (substeps > 1) need_shares(rows, cols, quadrant_x, quadrant_y);
  if ((substeps > 1 || squeeze.passes > 1) && in.gradient_scale > 0.0f) {
    // The head's underside over each cell, where the step's contact found it pressing: what a
    // sub-step's penetration, and a squeeze pass's after the first, measures against. (Where
    // it did not press, its underside lies somewhere above the paint: it presses there in no
    // sub-step. Only the squeeze measures against it.)
    const std::size_t n = win_.padded();
    for (std::size_t i = 0; i < n; ++i)
      head_level_[i] = pen_[i] > 0.0f ? ground_[i] + wet_[i] - pen_[i] : 1e30f;
  }
  if (in.sharing_binds) share_brush_cells(cells, in.inv_deposit_share);
  bool first_pass = true;  // of the advection's sub-steps
  const auto advect_rows = [&](int r0, int r1) {
    for (int y = r0; y < r1; ++y) {
      const int lo = span_lo_[static_cast<std::size_t>(y)];
      const int hi = span_hi_[static_cast<std::size_t>(y)];
      // Outside the span the step's grids hold the input (the squeeze reads neighbours);
      // after the first pass the grid written holds it already (a long step's sub-steps go
      // from the gathered grids to the new_ ones and back within the spans only).
      const std::size_t row = static_cast<std::size_t>(y + 1) * win_.stride() + 1;
      for (std::size_t k = 0; k < from_.size() && first_pass; ++k) {
        std::copy_n(from_[k] + row, lo, to_[k] + row);
        std::copy_n(from_[k] + row + hi, cols - hi, to_[k] + row + hi);
      }
      advection_.apply_span(from_.data(), to_.data(), static_cast<int>(from_.size()), y, lo, hi);
    }
  };
  // A sub-step's shares: its contact's velocities, on the volume it starts from. Each row's
  // shares need only that row's, so a sub-step's pass prepares the next one's.
  // Sub-step j (from 1) has the contact shifted by shifts_[j - 1] (none for the last) and
  // moves by sub_moves_[j - 1].
  const auto shift_of = [&](int j) {
    return j < substeps ? shifts_[static_cast<std::size_t>(j - 1)] : Shift{0, 0};
  };
  const auto prepare_rows = [&](int j, const float* volume, int r0, int r1) {
    const Shift shift = shift_of(j);
    const SubMove& sub = sub_moves_[static_cast<std::size_t>(j - 1)];
    shifted_velocity_rows(in, shift.x, shift.y, static_cast<float>(drag * sub.x),
                          static_cast<float>(drag * sub.y), r0, r1);
    advection_.prepare_quadrant_spans(r0, r1, vx_.data(), vy_.data(), volume, in.min_film_mm,
                                      need_lo_.data(), need_hi_.data());
  };
  const auto& m = in.placement.to_canvas;
  // Canvas rows that share a brush cell lie less than a chunk apart, so chunks of one parity
  // never write the same brush cell: each set runs in parallel, and every brush cell's sum
  // has one fixed order.
  const int chunk = static_cast<int>(std::floor(std::abs(m[2]) + std::abs(m[3]))) + 2;
  const bool squeezes = in.gradient_scale > 0.0f;
  swept_ = substeps > 1;
  faces_in_range_ = false;
  if (!swept_) {
    // 3. One step: the drag and the film split (which reads the step's input, wet_,
    // untouched), the brush gives what the canvas took, and the squeeze's faces.
    advection_.use_prepared_quadrant(quadrant_x, quadrant_y);
    parallel_rows(rows, cols, [&](int r0, int r1) {
      advect_rows(r0, r1);
      if (transfers) transfer_rows(in, r0, r1);
    });
    if (transfers || squeezes) {
      parallel_row_chunks(rows, chunk, cols, [&](int r0, int r1) {
        if (transfers) transfer_to_brush(brush, slot_count, r0, r1);
        if (squeezes && squeeze.passes == 1)
          squeeze_rows(pen_.data(), Shift{0, 0}, in.gradient_scale, squeeze.reach, r0, r1);
      });
      if (transfers) clamp_brush(brush, slot_count);
      if (squeezes && squeeze.passes > 1)
        squeeze_in_passes(Shift{0, 0}, 0.0f, in.gradient_scale, squeeze, slot_count);
    }
  } else {
    // 3. A long step: its sub-steps each drag, split the film and squeeze with the head
    // where it was then (the step's contact shifted back along the move) and their share of
    // the step's distance and time, the brush giving and taking as it goes. Only the contact
    // is found once. Done once for the whole step at its end, the split met each cell with
    // one brush row a step, which one by where the cell lay between two step ends, and the
    // squeeze saturated and pushed up the head's trailing edge there: a ridge every step,
    // and edges that long steps left flatter than short ones. Each sub-step goes from the
    // gathered grids (wet_, pigment_) to the new_ ones and its squeeze back; the last
    // sub-step's squeeze is applied as the result is scattered, as a short step's is.
    if (transfers) std::fill_n(exchanged_.begin(), cells, 0.0f);
    // The faces a sub-step's squeeze can move paint across: around each row's active span.
    std::fill(face_east_.begin(), face_east_.begin() + static_cast<std::ptrdiff_t>(win_.padded()),
              0.0f);
    std::fill(face_south_.begin(), face_south_.begin() + static_cast<std::ptrdiff_t>(win_.padded()),
              0.0f);
    face_lo_.assign(static_cast<std::size_t>(rows), 0);
    face_hi_.assign(static_cast<std::size_t>(rows), 0);
    for (int y = 0; y < rows; ++y) {
      int lo = cols, hi = 0;
      for (int near = std::max(y - 1, 0); near <= std::min(y + 1, rows - 1); ++near) {
        const auto k = static_cast<std::size_t>(near);
        if (span_hi_[k] <= span_lo_[k]) continue;
        lo = std::min(lo, span_lo_[k] - 1);
        hi = std::max(hi, span_hi_[k]);
      }
      face_lo_[static_cast<std::size_t>(y)] = std::clamp(lo, 0, cols);
      face_hi_[static_cast<std::size_t>(y)] = std::clamp(hi, 0, cols);
    }
    faces_in_range_ = true;
    const double walked = std::hypot(move_x, move_y);
    parallel_rows(rows, cols, [&](int r0, int r1) { prepare_rows(1, wet_.data(), r0, r1); });
    double progress = 0.0;  // of the step's path, after this sub-step
    for (int j = 1; j <= substeps; ++j) {
      const Shift here = shift_of(j);
      const double share = walked > 0.0
                               ? sub_moves_[static_cast<std::size_t>(j - 1)].length / walked
                               : 1.0 / substeps;
      progress = j == substeps ? 1.0 : std::min(progress + share, 1.0);
      // The tip went from depth_from to the pose's depth along the step.
      const auto level_offset = static_cast<float>((pose.depth_mm - depth_from) * (1.0 - progress));
      const auto relax =
          static_cast<float>(transfer_relaxation(share * distance_mm, share * seconds, params));
      advection_.use_prepared_quadrant(quadrant_x, quadrant_y);
      parallel_rows(rows, cols, [&](int r0, int r1) {
        advect_rows(r0, r1);
        if (transfers)
          shifted_transfer_rows(in, here, relax, wet_.data(), new_wet_.data(), new_pigment_.data(),
                                r0, r1);
        if (squeezes) sub_step_penetration_rows(here, level_offset, r0, r1);
      });
      // The brush gives what the canvas took, in canvas order on one thread (a sub-step's
      // exchange is small: two passes of row chunks cost more), beside the squeeze's faces.
      const auto c = static_cast<float>(in.gradient_scale * share);
      tbb::parallel_invoke(
          [&] {
            if (transfers) shifted_transfer_to_brush(brush, slot_count, here, 0, rows);
          },
          [&] {
            if (squeezes) squeeze_in_passes(here, level_offset, c, squeeze, slot_count);
          });
      if (j == substeps) {
        if (transfers) clamp_brush(brush, slot_count);
        break;
      }
      // (Without a squeeze the faces stay 0, zeroed above: the sub-step's result is copied.)
      parallel_rows(rows, cols, [&](int r0, int r1) {
        apply_squeeze_rows(slot_count, r0, r1);
        prepare_rows(j + 1, wet_.data(), r0, r1);
      });
      first_pass = false;
    }
  }
  // Paint in the bristles flows toward the tips that gave theirs away: over every
  // kBrushFlowBatchCells cells travelled at once (the relaxation composes over distance).
  brush_flow_pending_mm_ += distance_mm;
  if (brush_flow_pending_mm_ >= kBrushFlowBatchCells * cell_mm - 1e-9)
    finish_stroke(brush, slot_count, params);

  // 4. The squeeze applied, and the result written back to the tiles.
  scatter(canvas, slot_count, before_change, squeezes);
  last_window_cells_ = cells;
  return true;
}

}  // namespace impasto::paintcore
