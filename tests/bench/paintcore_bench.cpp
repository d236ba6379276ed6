// Simulation speed: one step of the whole IMPaSTo pipeline per iteration, for the brush sizes
// IMPaSTo reported (26 and 88 cells) and the 128-cell target.
#include <benchmark/benchmark.h>

#include "impasto/bench/simulation.hpp"

namespace {

void BM_PaintStep(benchmark::State& state) {
  const int brush = static_cast<int>(state.range(0));
  double seconds = 0, steps = 0;
  for (auto _ : state) {
    const auto r = impasto::bench::run_sim_benchmark(brush, 200);
    seconds += r.seconds;
    steps += static_cast<double>(r.steps);
    state.SetIterationTime(r.seconds);
  }
  state.counters["cells_per_second"] = benchmark::Counter(steps * brush * brush / seconds);
  state.counters["steps_per_second"] = benchmark::Counter(steps / seconds);
}
BENCHMARK(BM_PaintStep)->Arg(26)->Arg(88)->Arg(128)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
