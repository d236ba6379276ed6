#pragma once
// A repeatable measurement of simulation speed, shared by `impasto bench sim` and the Google
// Benchmark: a round brush of N x N cells, full of paint, strokes back and forth across a
// painted canvas one cell per step, so every step does the whole pipeline.
#include <cstdint>

namespace impasto::paintcore {

struct SimBenchmarkResult {
  int brush_cells = 0;                 // N: the brush grid is N x N cells
  std::uint64_t steps = 0;             // simulation steps timed
  double seconds = 0;                  // wall time of those steps
  double cells_per_second = 0;         // N^2 * steps / seconds (brush cells, as IMPaSTo counts)
  double window_cells_per_second = 0;  // cells actually processed (brush window + margin)
  double steps_per_second = 0;
};

// Runs `steps` timed steps (after a short warm-up) with `threads` threads (0: all cores).
SimBenchmarkResult run_sim_benchmark(int brush_cells, int steps, int threads = 0);

}  // namespace impasto::paintcore
