#pragma once
// Row-parallel loops over a window. Every row is written by exactly one task and no result
// depends on how rows are split, so any thread count gives bit-identical results.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace impasto::paintcore {

// Calls body(y0, y1) on disjoint row ranges covering [0, rows); chunks hold >= ~4096 cells
// so that small windows run on one thread without scheduling overhead.
template <typename Body>
void parallel_rows(int rows, int cells_per_row, const Body& body) {
  const int grain = std::max(1, 4096 / std::max(1, cells_per_row));
  if (rows <= grain) {
    body(0, rows);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, rows, grain),
                    [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

}  // namespace impasto::paintcore
