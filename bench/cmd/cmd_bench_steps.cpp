// impasto bench steps: the cost and error of long steps (SimulationParams::long_step_share)
// against one-cell steps, for a big brush's mouse stroke (bench::run_long_step_benchmark).
#include <impasto/bench/simulation.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_steps_cmd {
namespace {

using namespace impasto::bench;  // the measures (bench/)

struct BenchStepsArgs {
  bool json = false;
  int runs = 3;
  int threads = 0;
  std::vector<int> brushes{64, 128};
  std::vector<double> shares{0.03125, 0.0625, 0.125};
  std::vector<std::string> params;  // NAME=VALUE
};

void run(const BenchStepsArgs& args) {
  if (args.threads < 0) throw std::runtime_error("bench steps: --threads must be >= 0");
  paintcore::SimulationParams params;
  for (const std::string& assignment : args.params) paintcore::set_param(params, assignment);
  paintcore::validate(params);
  if (!args.json)
    std::printf("%6s %7s %5s %6s %9s %8s %9s %9s %8s %9s %8s %8s %9s\n", "brush", "share", "step",
                "steps", "ms", "speed-up", "mean h mm", "|dh| mean", "|dh| max", "4x4 mean",
                "4x4 max", "white mn", "white max");
  ProgressReporter progress("bench steps", "brushes");
  std::uint64_t done = 0;
  for (const int brush : args.brushes) {
    const auto results =
        bench::run_long_step_benchmark(brush, args.shares, args.runs, args.threads, params);
    progress.update(++done, args.brushes.size());
    progress.clear();
    const double reference_seconds = results.front().seconds;
    for (const auto& r : results) {
      if (args.json) {
        std::cout << nlohmann::json{{"brush", r.brush_cells},
                                    {"long_step_share", r.share},
                                    {"step_cells", r.step_cells},
                                    {"steps", r.steps},
                                    {"seconds", r.seconds},
                                    {"mean_height_mm", r.mean_height_mm},
                                    {"mean_height_error_mm", r.mean_height_error_mm},
                                    {"max_height_error_mm", r.max_height_error_mm},
                                    {"mean_block_error_mm", r.mean_block_error_mm},
                                    {"max_block_error_mm", r.max_block_error_mm},
                                    {"mean_white_error", r.mean_white_error},
                                    {"max_white_error", r.max_white_error},
                                    {"volume_mm3", r.volume_mm3},
                                    {"volume_error_mm3", r.volume_error_mm3}}
                  << "\n";
      } else {
        std::printf("%6d %7.4g %5.3g %6llu %9.1f %8.2f %9.4f %9.4f %8.4f %9.4f %8.4f %8.4f %9.4f\n",
                    r.brush_cells, r.share, r.step_cells, static_cast<unsigned long long>(r.steps),
                    1e3 * r.seconds, reference_seconds / r.seconds, r.mean_height_mm,
                    r.mean_height_error_mm, r.max_height_error_mm, r.mean_block_error_mm,
                    r.max_block_error_mm, r.mean_white_error, r.max_white_error);
      }
    }
    progress.update(done, args.brushes.size());
  }
}

const CommandRegistrar registrar("bench steps", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  auto args = std::make_shared<BenchStepsArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "steps",
      "Long steps' cost and error against one-cell steps: a big brush's arc through wet paint");
  add_json_flag(*cmd, args->json, "one object a line, per brush size and share");
  cmd->add_option("--runs", args->runs, "Timed runs of each stroke (the median is reported)")
      ->check(finite_range(1, 100));
  add_threads_option(*cmd, args->threads);
  cmd->add_option("--brush", args->brushes, "Brush sizes in cells across")
      ->check(finite_range(8, 1024));
  cmd->add_option("--share", args->shares,
                  "long_step_share values to compare with one-cell steps (share of the width)")
      ->check(finite_range(0.0, 0.5));
  cmd->add_option("--param", args->params, vocabulary_help("--param"));
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_steps_cmd
