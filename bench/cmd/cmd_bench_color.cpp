// impasto bench color: colour error of N-wavelength rendering against the 1-nm full
// spectrum, by the kinds of paint paintings are made of (the bare ground, masstones, tints,
// glazes 0.5-50 optical units thick, wet over dry stacks, and the painted cells of the bundled
// replays), mean, 95th percentile and max CIEDE2000 each, and the cost per cell of each N, for
// float and half storage of the baked reflectance. --samples standard: the older sample set
// (masstones, one tint, 50/50 mixes and one glaze of every pigment, bare K-M). For the rules
// trained on the palette (fitted, optimised) also their error on the training paints and the
// time to build the rule for a light.
#include <impasto/data/cie.hpp>
#include <impasto/data/colorimetry.hpp>
#include <impasto/data/data_dir.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/input/stroke_import.hpp>
#include <impasto/render/chromatic_adaptation.hpp>
#include <impasto/render/color_accuracy.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/node_cache.hpp>
#include <impasto/render/node_optimisation.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render/tile_renderer.hpp>
#include <impasto/session/replay.hpp>
#include <impasto/session/swatch.hpp>

#include <algorithm>
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
  std::string samples = "paintings";  // or "standard"
};

// The replays whose painted cells are the "painting" class: the demo and the bundled studies.
constexpr const char* kPaintingReplays[] = {"demo.dat", "metallic.strokes", "surface_study.strokes",
                                            "medium_study.strokes"};

struct ReplayedPainting {
  std::string name;
  paintcore::Painting painting;
  std::vector<std::pair<int, int>> cells;  // painted: more than session::kPaintedAboveMm
};

std::vector<ReplayedPainting> replay_paintings() {
  std::vector<ReplayedPainting> out;
  for (const char* name : kPaintingReplays) {
    const input::StrokeFile file = input::load_strokes_any(data::data_dir() / "strokes" / name);
    session::ReplayOptions options;
    paintcore::Painting painting = session::replay(file, options);
    const paintcore::Canvas& canvas = painting.canvas();
    std::vector<std::pair<int, int>> cells;
    for (int t = 0; t < canvas.tiles_x() * canvas.tiles_y(); ++t) {
      const paintcore::Tile* tile = canvas.tile(t);
      if (!tile) continue;
      const int x0 = t % canvas.tiles_x() * paintcore::kTileSize;
      const int y0 = t / canvas.tiles_x() * paintcore::kTileSize;
      for (int c = 0; c < paintcore::kTileCells; ++c) {
        const int x = x0 + c % paintcore::kTileSize, y = y0 + c / paintcore::kTileSize;
        if (x >= canvas.width_cells() || y >= canvas.height_cells()) continue;
        const auto i = static_cast<std::size_t>(c);
        if (tile->wet_volume_mm[i] + tile->dry_height_mm[i] > session::kPaintedAboveMm)
          cells.push_back({x, y});
      }
    }
    out.push_back({name, std::move(painting), std::move(cells)});
  }
  return out;
}

// L*a*b* (relative to D65) of each of `cells` of the painting rendered with `settings`.
std::vector<data::Lab> rendered_cells(const ReplayedPainting& replayed, RenderSettings settings) {
  settings.display = DisplayEncoding::linear_srgb;
  TileRenderer renderer(settings, SpectralPalette(settings, replayed.painting));
  renderer.render_all(replayed.painting.canvas());
  const Image image = renderer.image();
  static const auto to_xyz = invert_3x3(xyz_to_linear_srgb());
  const data::Xyz white{100 * kD65WhiteXyz[0], 100 * kD65WhiteXyz[1], 100 * kD65WhiteXyz[2]};
  std::vector<data::Lab> out;
  for (const auto& [x, y] : replayed.cells) {
    const float* rgb = image.pixel(x, y);
    double xyz[3];
    for (std::size_t i = 0; i < 3; ++i)
      xyz[i] = 100.0 *
               (to_xyz[3 * i] * rgb[0] + to_xyz[3 * i + 1] * rgb[1] + to_xyz[3 * i + 2] * rgb[2]);
    out.push_back(data::xyz_to_lab({xyz[0], xyz[1], xyz[2]}, white));
  }
  return out;
}

// Every painted cell of each replay rendered (the default renderer, its lamp and relief)
// under `light` with `nodes` wavelengths (0: the full spectrum, the reference).
std::vector<std::vector<data::Lab>> painted_cells(const std::vector<ReplayedPainting>& paintings,
                                                  const std::string& light, int nodes,
                                                  NodeWeights weights) {
  RenderSettings settings;
  settings.light = light;
  settings.node_weights = weights;
  settings.wavelengths = nodes;
  std::vector<std::vector<data::Lab>> out;
  for (const ReplayedPainting& replayed : paintings)
    out.push_back(rendered_cells(replayed, settings));
  return out;
}

// The "painting" class: the cells at `nodes` wavelengths against the reference's.
ClassError painting_cells_error(const std::vector<ReplayedPainting>& paintings,
                                const std::vector<std::vector<data::Lab>>& reference,
                                const std::string& light, int nodes, NodeWeights weights) {
  const std::vector<std::vector<data::Lab>> got = painted_cells(paintings, light, nodes, weights);
  std::vector<std::pair<double, std::string>> errors;
  for (std::size_t p = 0; p < paintings.size(); ++p)
    for (std::size_t i = 0; i < got[p].size(); ++i) {
      const auto [x, y] = paintings[p].cells[i];
      errors.push_back(
          {data::ciede2000(reference[p][i], got[p][i]),
           paintings[p].name + " (" + std::to_string(x) + ", " + std::to_string(y) + ")"});
    }
  return summarise_errors("painting", errors);
}

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

// Per light and node count (float storage), each class's mean / 95th percentile / max.
void print_classes(const std::vector<AccuracyResult>& rows) {
  std::printf("\nBy class: mean / p95 / max dE00 against the full spectrum (float storage)\n");
  std::printf("%-6s %4s", "light", "N");
  for (const char* kind : kColorClasses) std::printf(" %20s", kind);
  std::printf("\n");
  for (const AccuracyResult& r : rows) {
    if (r.nodes == 0 || r.storage != ReflectanceStorage::float32) continue;
    std::printf("%-6s %4d", r.light.c_str(), r.nodes);
    for (const char* kind : kColorClasses) {
      const auto c = std::find_if(r.classes.begin(), r.classes.end(),
                                  [&](const ClassError& e) { return e.kind == kind; });
      if (c == r.classes.end() || c->count == 0) {
        std::printf(" %20s", "-");
        continue;
      }
      char cell[64];
      std::snprintf(cell, sizeof cell, "%.2f/%.2f/%.2f", c->mean_de00, c->p95_de00, c->max_de00);
      std::printf(" %20s", cell);
    }
    std::printf("\n");
  }
  // The first row (float storage, the first node count) holds every class.
  std::printf("%-11s", "samples");
  if (!rows.empty())
    for (const char* kind : kColorClasses) {
      const auto c = std::find_if(rows.front().classes.begin(), rows.front().classes.end(),
                                  [&](const ClassError& e) { return e.kind == kind; });
      std::printf(" %20d", c == rows.front().classes.end() ? 0 : c->count);
    }
  std::printf("\n");
}

void run(const BenchColorArgs& args) {
  const NodeWeights weights = parse_node_weights(args.weights);
  const bool trained = weights == NodeWeights::fitted || weights == NodeWeights::optimised;
  const std::vector<data::Pigment>& pigments = data::PigmentDatabase::defaults().all();
  const bool by_class = args.samples == "paintings";
  const std::vector<ColorSample> samples =
      by_class ? painting_color_samples(pigments) : standard_color_samples(pigments);
  std::vector<ReplayedPainting> paintings;
  if (by_class) paintings = replay_paintings();

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
    // The replays' cells at the full spectrum, once per light for every node count.
    const std::vector<std::vector<data::Lab>> reference_cells =
        by_class ? painted_cells(paintings, light_name, 0, weights)
                 : std::vector<std::vector<data::Lab>>{};
    for (int n : node_counts) {
      rows.push_back(evaluate_color_accuracy(light, light_name, n, pigments, samples,
                                             ReflectanceStorage::float32, weights,
                                             args.timing_cells));
      if (by_class && n != 0)
        rows.back().classes.push_back(
            painting_cells_error(paintings, reference_cells, light_name, n, weights));
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
      for (const ClassError& c : r.classes)
        row["classes"][c.kind] = {{"count", c.count},
                                  {"mean_de00", c.mean_de00},
                                  {"p95_de00", c.p95_de00},
                                  {"max_de00", c.max_de00},
                                  {"worst", c.worst}};
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
  if (by_class) print_classes(rows);
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
  cmd->add_option("--samples", args->samples,
                  "paintings: the classes paintings are made of, the bundled replays' cells "
                  "included (docs/color-accuracy.md); standard: the older set, bare K-M")
      ->check(CLI::IsMember({"paintings", "standard"}));
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_color_cmd
