#pragma once
// A repeatable measurement of simulation speed, shared by `impasto bench sim` and the Google
// Benchmark: a round brush of N x N cells, full of paint, strokes back and forth across a
// painted canvas one cell per step, so every step does the whole pipeline.
#include <cstdint>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::bench {

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

// How far a canvas's wet paint lies from a reference's, over the cells where either holds
// paint (more than 0.001 mm): each cell, and the means of 4 x 4 cell blocks (0.34 mm at 300
// dpi), which show the mark's shape without the bristles' furrows that move with any change
// of path. Throws std::invalid_argument when the canvases differ in size.
struct HeightDifference {
  double mean_height_mm = 0;  // the reference's mean
  double mean_error_mm = 0, max_error_mm = 0;
  double mean_block_error_mm = 0, max_block_error_mm = 0;
};
HeightDifference compare_wet_heights(const paintcore::Canvas& a,
                                     const paintcore::Canvas& reference);

// The cost and error of long steps (paintcore::SimulationParams::long_step_share): on a 300-dpi
// canvas with a band of blue across it, a round brush N cells across loaded with white (half its
// area times 0.5 mm) draws an arc through the band, sampled like a mouse (8 ms, a quarter
// of the brush apart); the same stroke with one-cell steps is the reference.
struct LongStepResult {
  int brush_cells = 0;
  double share = 0;                 // long_step_share (0: the one-cell reference)
  double step_cells = 0;            // the longest step it allows, cells
  std::uint64_t steps = 0;          // simulation steps of the stroke
  double seconds = 0;               // wall time of the stroke (median of runs)
  double mean_height_mm = 0;        // the reference's mean wet height where it holds paint
  double mean_height_error_mm = 0;  // |wet height - the reference's|, mean over those cells
  double max_height_error_mm = 0;
  // The same for the mean heights of 4 x 4 cell blocks (0.34 mm): the mark's shape without
  // the bristles' furrows, which move with any change of path.
  double mean_block_error_mm = 0;
  double max_block_error_mm = 0;
  double mean_white_error = 0;  // |white's share of the pigment - the reference's|, mean
  double max_white_error = 0;   // (over cells holding at least 0.01 mm in both)
  double volume_error_mm3 = 0;  // canvas + brush - (loaded - wiped): what was not conserved
  double volume_mm3 = 0;        // loaded - wiped
};
// The one-cell reference first, then each share; `runs` timed repeats (the median is kept).
// `params` holds the rest of the model (long_step_drag_cells, say).
std::vector<LongStepResult> run_long_step_benchmark(int brush_cells,
                                                    const std::vector<double>& shares, int runs,
                                                    int threads = 0,
                                                    const paintcore::SimulationParams& params = {});

}  // namespace impasto::bench
