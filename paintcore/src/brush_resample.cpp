#include "impasto/paintcore/brush_resample.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace impasto::paintcore {
namespace {

// One cell of a row of the new grid that a cell of the old row overlaps, and the share of
// the old cell it gets.
struct Overlap {
  int cell;
  double share;
};

// For each of `from_n` cells along [-1, 1], the cells of `to_n` along the same span that it
// overlaps. Edges are integers on a common scale (from_n * to_n units), so overlaps are exact.
std::vector<std::vector<Overlap>> row_overlaps(int from_n, int to_n) {
  std::vector<std::vector<Overlap>> overlaps(static_cast<std::size_t>(from_n));
  for (int i = 0; i < from_n; ++i) {
    const long lo = static_cast<long>(i) * to_n, hi = lo + to_n;
    for (int j = static_cast<int>(lo / from_n); j < to_n; ++j) {
      const long cell_lo = static_cast<long>(j) * from_n, cell_hi = cell_lo + from_n;
      if (cell_lo >= hi) break;
      const long overlap = std::min(hi, cell_hi) - std::max(lo, cell_lo);
      if (overlap > 0)
        overlaps[static_cast<std::size_t>(i)].push_back(
            {j, static_cast<double>(overlap) / static_cast<double>(to_n)});
    }
  }
  return overlaps;
}

// For every cell of `brush`, the covered cell nearest to it (itself when covered), by a
// breadth-first search outward from the covered cells (4-neighbours, rows first on ties).
std::vector<std::size_t> nearest_covered(const Brush& brush) {
  const int n = brush.cells_across();
  const std::size_t cells = brush.cell_count();
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> nearest(cells, kNone);
  std::vector<std::size_t> queue;
  queue.reserve(cells);
  for (std::size_t c = 0; c < cells; ++c)
    if (brush.covers()[c]) {
      nearest[c] = c;
      queue.push_back(c);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    const int x = static_cast<int>(c % static_cast<std::size_t>(n));
    const int y = static_cast<int>(c / static_cast<std::size_t>(n));
    const int steps[4][2] = {{0, -1}, {-1, 0}, {1, 0}, {0, 1}};
    for (const auto& step : steps) {
      const int nx = x + step[0], ny = y + step[1];
      if (nx < 0 || ny < 0 || nx >= n || ny >= n) continue;
      const std::size_t next =
          static_cast<std::size_t>(ny) * static_cast<std::size_t>(n) + static_cast<std::size_t>(nx);
      if (nearest[next] != kNone) continue;
      nearest[next] = nearest[c];
      queue.push_back(next);
    }
  }
  return nearest;
}

// Sums a float grid in double, in cell order (as Painting::brush_totals does).
double sum(const float* values, std::size_t count) {
  double total = 0.0;
  for (std::size_t c = 0; c < count; ++c) total += values[c];
  return total;
}

// Resamples one quantity (volume or a pigment) of the old grid into `out`; returns what
// rounding to float left over, in mm of height summed over cells.
double resample_quantity(const Brush& from, const float* in, const Brush& to, float* out,
                         const std::vector<std::vector<Overlap>>& overlaps,
                         const std::vector<std::size_t>& nearest) {
  const int from_n = from.cells_across(), to_n = to.cells_across();
  const std::size_t to_cells = to.cell_count();
  std::vector<double> moved(to_cells, 0.0);
  for (int y = 0; y < from_n; ++y)
    for (int x = 0; x < from_n; ++x) {
      const double value = in[static_cast<std::size_t>(y) * from_n + x];
      if (value == 0.0) continue;
      for (const Overlap& row : overlaps[static_cast<std::size_t>(y)])
        for (const Overlap& column : overlaps[static_cast<std::size_t>(x)])
          moved[static_cast<std::size_t>(row.cell) * to_n + column.cell] +=
              value * row.share * column.share;
    }
  // Paint beyond the new head's underside has nowhere to sit: it goes to the nearest cell
  // the head covers.
  for (std::size_t c = 0; c < to_cells; ++c)
    if (!to.covers()[c] && moved[c] != 0.0) moved[nearest[c]] += std::exchange(moved[c], 0.0);
  for (std::size_t c = 0; c < to_cells; ++c) out[c] = static_cast<float>(moved[c]);
  // Rounding to float changed the sum: give the difference to the fullest cell, whose float
  // spacing is the coarsest, until the sums agree or cannot get closer.
  const double target = sum(in, from.cell_count());
  double residue = target - sum(out, to_cells);
  for (int pass = 0; pass < 4 && residue != 0.0; ++pass) {
    float& fullest = *std::max_element(out, out + to_cells);
    fullest = std::max(0.0f, static_cast<float>(static_cast<double>(fullest) + residue));
    const double next = target - sum(out, to_cells);
    if (next == residue) break;
    residue = next;
  }
  return residue;
}

}  // namespace

PaintTotals resample_brush_paint(const Brush& from, Brush& to, double cell_area_mm2) {
  to.ensure_slots(from.slot_count());
  to.set_body(from.body());      // the paint keeps its body on the new head
  to.set_medium(from.medium());  // and its medium
  std::fill(to.volume_mm().begin(), to.volume_mm().end(), 0.0f);
  std::fill(to.pigment_mm().begin(), to.pigment_mm().end(), 0.0f);
  PaintTotals lost{0.0, std::vector<double>(static_cast<std::size_t>(to.slot_count()), 0.0)};
  if (from.empty() || to.empty()) return lost;
  const auto overlaps = row_overlaps(from.cells_across(), to.cells_across());
  const auto nearest = nearest_covered(to);
  lost.volume = resample_quantity(from, from.volume_mm().data(), to, to.volume_mm().data(),
                                  overlaps, nearest) *
                cell_area_mm2;
  for (int s = 0; s < from.slot_count(); ++s) {
    const std::size_t from_offset = static_cast<std::size_t>(s) * from.cell_count();
    const std::size_t to_offset = static_cast<std::size_t>(s) * to.cell_count();
    lost.pigment[static_cast<std::size_t>(s)] =
        resample_quantity(from, from.pigment_mm().data() + from_offset, to,
                          to.pigment_mm().data() + to_offset, overlaps, nearest) *
        cell_area_mm2;
  }
  return lost;
}

}  // namespace impasto::paintcore
