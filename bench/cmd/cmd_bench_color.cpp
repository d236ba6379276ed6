// impasto bench color: colour error of N-wavelength rendering against the 1-nm full
// spectrum (CIEDE2000 over masstones, tints, 50/50 mixes and glazes of every pigment), and
// the cost per cell of each N, for float and half storage of the baked reflectance. For the
// rules trained on the palette (fitted, optimised) also their error on the training paints
// and the time to build the rule for a light.
#include <impasto/data/cie.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/render/color_accuracy.hpp>
#include <impasto/render/node_cache.hpp>
#include <impasto/render/node_optimisation.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.hpp"
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_color_cmd {
namespace {

using namespace impasto::render;

struct BenchColorArgs {
  bool json = false;
  std::vector<int> nodes{3, 4, 6, 8, 12, 16};
  std::vector<std::string> lights{"D65", "A", "F11"};
  std::string weights{util::name_of(kNodeWeightsNames, RenderSettings{}.node_weights)};
  int timing_cells = 20000;
  bool half = true;
};

// A rule trained on the palette: its error on the training paints (the Gaussian rule's
// beside it) and the wall time to build it for this light (all cores).
struct TrainingRow {
  int nodes = 0;
  std::string light;
  RuleError rule, gauss;
  double build_ms = 0.0;
  int paints = 0;
};

TrainingRow train_rule(const data::Spectrum& light, const std::string& light_name, int nodes,
                       NodeWeights weights, const std::vector<data::Pigment>& pigments) {
  const auto& cmf = data::cie1931_2deg();
  const data::Spectrum ground = hiding_reflectance(
      data::PigmentDatabase::defaults().get("White"));  // the ground of the accuracy samples
  const auto start = std::chrono::steady_clock::now();
  // Built from scratch (what a new palette or light costs once) and kept: the accuracy rows
  // below read it from the cache.
  const SpectralSampling rule =
      build_palette_rule(light, cmf, nodes, {}, weights, pigments, ground);
  const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
  store_node_rule(palette_rule_key(light, cmf, nodes, {}, weights, pigments, ground), rule);
  const PaletteTrainingSet training(light, cmf, {}, pigments, ground);
  return {nodes,
          light_name,
          training.error_of(rule),
          training.error_of(make_spectral_sampling(light, cmf, nodes)),
          elapsed.count(),
          training.paint_count()};
}

void run(const BenchColorArgs& args) {
  const NodeWeights weights = parse_node_weights(args.weights);
  const bool trained = weights == NodeWeights::fitted || weights == NodeWeights::optimised;
  const std::vector<data::Pigment>& pigments = data::PigmentDatabase::defaults().all();
  const std::vector<ColorSample> samples = standard_color_samples(pigments);

  std::vector<AccuracyResult> rows;
  std::vector<TrainingRow> training_rows;
  const std::size_t n = args.nodes.size();
  const std::uint64_t steps =
      args.lights.size() * ((trained ? n : 0) + n + 1 + (args.half ? n : 0));
  std::uint64_t done = 0;
  ProgressReporter progress("bench color", "rows");
  for (const std::string& light_name : args.lights) {
    const data::Spectrum light = data::light_from_spec(light_name);
    if (trained) {
      for (int n : args.nodes) {
        training_rows.push_back(train_rule(light, light_name, n, weights, pigments));
        progress.update(++done, steps);
      }
    }
    std::vector<int> node_counts = args.nodes;
    node_counts.push_back(0);  // the full spectrum: its cost (its error is 0 by definition)
    for (int n : node_counts) {
      rows.push_back(evaluate_color_accuracy(light, light_name, n, pigments, samples,
                                             ReflectanceStorage::float32, weights,
                                             args.timing_cells));
      progress.update(++done, steps);
      if (args.half && n != 0) {
        rows.push_back(evaluate_color_accuracy(light, light_name, n, pigments, samples,
                                               ReflectanceStorage::float16, weights,
                                               args.timing_cells));
        progress.update(++done, steps);
      }
    }
  }
  progress.finish();

  if (args.json) {
    for (const AccuracyResult& r : rows) {
      nlohmann::json row{{"n", r.nodes},
                         {"light", r.light},
                         {"mean_de00", r.mean_de00},
                         {"max_de00", r.max_de00},
                         {"ns_per_cell", r.ns_per_cell},
                         {"storage", util::name_of(kReflectanceStorageNames, r.storage)},
                         {"worst", r.worst_sample}};
      std::cout << row.dump() << "\n";
    }
    for (const TrainingRow& r : training_rows) {
      nlohmann::json row{{"training", true},
                         {"n", r.nodes},
                         {"light", r.light},
                         {"mean_de00", r.rule.mean_de00},
                         {"max_de00", r.rule.max_de00},
                         {"gauss_mean_de00", r.gauss.mean_de00},
                         {"gauss_max_de00", r.gauss.max_de00},
                         {"build_ms", r.build_ms}};
      std::cout << row.dump() << "\n";
    }
    return;
  }
  std::printf("%zu samples (%zu pigments), node weights: %s\n", samples.size(), pigments.size(),
              args.weights.c_str());
  std::printf("%-6s %4s %-6s %10s %10s %12s  %s\n", "light", "N", "store", "mean dE00", "max dE00",
              "ns/cell", "worst sample");
  for (const AccuracyResult& r : rows) {
    std::printf("%-6s %4s %-6s %10.4f %10.4f %12.1f  %s\n", r.light.c_str(),
                r.nodes == 0 ? "full" : std::to_string(r.nodes).c_str(),
                std::string(util::name_of(kReflectanceStorageNames, r.storage)).c_str(),
                r.mean_de00, r.max_de00, r.ns_per_cell,
                r.nodes == 0 ? "-" : r.worst_sample.c_str());
  }
  if (training_rows.empty()) return;
  std::printf("\nTraining paints (%d; not the samples above): %s rule vs Gauss, build time\n",
              training_rows.front().paints, args.weights.c_str());
  std::printf("%-6s %4s %10s %10s %11s %11s %10s\n", "light", "N", "mean dE00", "max dE00",
              "gauss mean", "gauss max", "build ms");
  for (const TrainingRow& r : training_rows) {
    std::printf("%-6s %4d %10.4f %10.4f %11.4f %11.4f %10.1f\n", r.light.c_str(), r.nodes,
                r.rule.mean_de00, r.rule.max_de00, r.gauss.mean_de00, r.gauss.max_de00, r.build_ms);
  }
}

const CommandRegistrar registrar("bench color", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "color", "CIEDE2000 of N-wavelength rendering vs the 1-nm spectrum, and ns per cell");
  auto args = std::make_shared<BenchColorArgs>();
  add_json_flag(*cmd, args->json,
                "one object a line: n, light, mean_de00, max_de00, ns_per_cell (n = 0: full "
                "spectrum), storage, worst");
  cmd->add_option("--nodes", args->nodes, "Wavelength counts to test (1..16)")
      ->check(finite_range(1, 16));
  cmd->add_option("--lights", args->lights, "Lights (D65, A, F11, blackbody:K, FILE.csv)");
  add_choice_option(*cmd, "--weights", args->weights, kNodeWeightsNames,
                    "Nodes and XYZ weights (optimised and fitted: trained on the palette)");
  cmd->add_option("--cells", args->timing_cells, "Cells per timing run (0: no timing)")
      ->check(finite_range(0, 10000000));
  cmd->add_flag("!--no-half", args->half, "Skip the half-storage rows");
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_color_cmd
