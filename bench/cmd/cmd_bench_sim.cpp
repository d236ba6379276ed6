// impasto bench sim: speed of the paint simulation for the brush sizes IMPaSTo reported
// (26 and 88 cells across; 77 k and 520 k cells/s on a 2004 GPU) and a 128-cell brush.
#include <impasto/bench/simulation.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "command.hpp"
#include "impasto/util/statistics.hpp"
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_sim_cmd {
namespace {

using namespace impasto::bench;  // the measures (bench/)

struct BenchSimArgs {
  bool json = false;
  int runs = 5;
  int steps = 300;
  int threads = 0;
  std::vector<int> brushes{26, 88, 128};
};

using util::median;

void run(const BenchSimArgs& args) {
  if (args.runs < 1) throw std::runtime_error("bench sim: --runs must be >= 1");
  if (args.threads < 0) throw std::runtime_error("bench sim: --threads must be >= 0");
  if (!args.json)
    std::printf("%8s %18s %16s %22s\n", "brush", "cells/s (brush)", "steps/s", "cells/s (window)");
  ProgressReporter progress("bench sim", "runs");
  const std::uint64_t total = args.brushes.size() * static_cast<std::uint64_t>(args.runs);
  std::uint64_t done = 0;
  for (const int brush : args.brushes) {
    std::vector<double> cells, steps, window;
    for (int r = 0; r < args.runs; ++r) {
      const auto result = bench::run_sim_benchmark(brush, args.steps, args.threads);
      progress.update(++done, total);
      cells.push_back(result.cells_per_second);
      steps.push_back(result.steps_per_second);
      window.push_back(result.window_cells_per_second);
    }
    progress.clear();
    if (args.json) {
      std::cout << nlohmann::json{{"brush", brush},
                                  {"cells_per_second", median(cells)},
                                  {"steps_per_second", median(steps)}}
                << "\n";
    } else {
      std::printf("%5dx%-3d %18.4g %16.4g %22.4g\n", brush, brush, median(cells), median(steps),
                  median(window));
    }
    progress.update(done, total);  // the bar again, below the row
  }
}

const CommandRegistrar registrar("bench sim", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  auto args = std::make_shared<BenchSimArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "sim", "Paint simulation speed: cell-steps and steps per second (median of runs)");
  add_json_flag(*cmd, args->json, "one object a line, per brush size");
  cmd->add_option("--runs", args->runs, "Runs per brush size (the median is reported)");
  cmd->add_option("--steps", args->steps, "Timed simulation steps per run")
      ->check(finite_range(1, 1000000));
  add_threads_option(*cmd, args->threads);
  cmd->add_option("--brush", args->brushes, "Brush sizes in cells across")
      ->check(finite_range(1, 1024));
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_sim_cmd
