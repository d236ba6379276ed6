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

// Calls body(y0, y1) on fixed chunks of `chunk` rows: every even chunk, in parallel, then
// every odd one. Chunks that run together are at least `chunk` rows apart, so a body may
// write anything that only rows less than `chunk` apart share; and as the chunks do not
// depend on the thread count, neither does the order of those writes.
template <typename Body>
void parallel_row_chunks(int rows, int chunk, int cells_per_row, const Body& body) {
  chunk = std::max(1, chunk);
  const int chunks = (rows + chunk - 1) / chunk;
  const int grain = std::max(1, 4096 / std::max(1, cells_per_row * chunk));
  for (int parity = 0; parity < 2; ++parity) {
    const int count = (chunks - parity + 1) / 2;  // chunks parity, parity + 2, ...
    const auto run = [&](int i0, int i1) {
      for (int i = i0; i < i1; ++i) {
        const int y0 = (2 * i + parity) * chunk;
        body(y0, std::min(rows, y0 + chunk));
      }
    };
    if (count <= grain)
      run(0, count);
    else
      tbb::parallel_for(tbb::blocked_range<int>(0, count, grain),
                        [&](const tbb::blocked_range<int>& r) { run(r.begin(), r.end()); });
  }
}

}  // namespace impasto::paintcore
