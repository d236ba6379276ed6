// impasto bench render: what a whole-canvas render costs on this machine. A painting (a file,
// or a synthetic one of --size cells, 62 % of its tiles painted with two layers and relief)
// is rendered once, then relit (a new light: paint and relief unchanged) with one thread and
// with all of them, and the image encoded to PNG: wall times (medians), ns per cell and the
// thread scaling.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/png_encoder.hpp>
#include <impasto/render/render_painting.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "command.hpp"
#include "impasto/util/statistics.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_render_cmd {
namespace {

using Clock = std::chrono::steady_clock;
using paintcore::kTileCells;
using paintcore::kTileSize;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the whole process (every thread), ms: against the wall time it shows how much
// of the time the threads worked, even when other programs hold the cores.
double process_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

struct BenchRenderArgs {
  std::string painting;            // empty: synthetic
  std::optional<CanvasSize> size;  // unset: 4096x4096
  std::string wavelengths = "8";
  std::string weights{
      util::name_of(render::kNodeWeightsNames, render::RenderSettings{}.node_weights)};
  int runs = 3;
  int threads = 0;         // the "all threads" case; 0: every core
  bool reference = false;  // the scalar per-cell reference instead of the spectral kernels
  bool json = false;
};

// The demo palette's eight pigments: a synthetic painting holds them all.
const std::vector<std::string> kSlots{"Blue Red Shade", "Cold Yellow", "Magenta",          "Green",
                                      "White",          "Red Oxide",   "Blue Green Shade", "Red"};

// A canvas with 62 % of its tiles painted (as a finished study: 2,550 of 4,096 at 4096²):
// a dry layer of two pigments under a wet layer of three, both varying cell to cell, in
// ridges 0.05-0.6 mm high that cast shadows. Deterministic.
paintcore::Canvas synthetic_canvas(int width, int height) {
  paintcore::Canvas canvas({width, height, 150.0, 1});
  const int slots = static_cast<int>(kSlots.size());
  canvas.dry_layers().emplace_back();
  for (int t = 0; t < canvas.tile_count(); ++t) {
    if ((t * 2654435761u) % 100u >= 62u) continue;  // a scattered 62 %
    paintcore::Tile& tile = canvas.ensure_tile(t, slots);
    const int tx = (t % canvas.tiles_x()) * kTileSize, ty = (t / canvas.tiles_x()) * kTileSize;
    const int a = t % slots, b = (t / 3 + 1) % slots, c = 4;  // two colours and white
    paintcore::DryTile dry;
    dry.tile_index = t;
    dry.volume_mm.assign(kTileCells, 0.04f);
    dry.slots = {static_cast<std::uint8_t>(std::min(a, (a + 5) % slots)),
                 static_cast<std::uint8_t>(std::max(a, (a + 5) % slots))};
    dry.pigment_mm.assign(2 * kTileCells, 0.01f);
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int x = tx + cell % kTileSize, y = ty + cell / kTileSize;
      const float ridge = 0.5f + 0.5f * static_cast<float>(std::sin(0.21 * x + 0.05 * y));
      const float v = 0.05f + 0.55f * ridge * ridge;
      const auto k = static_cast<std::size_t>(cell);
      tile.wet_volume_mm[k] = v;
      tile.dry_height_mm[k] = 0.04f;
      const float share = 0.5f + 0.5f * static_cast<float>(std::cos(0.013 * x - 0.017 * y));
      tile.pigment(a)[cell] = 0.4f * share * v;
      tile.pigment(b)[cell] += 0.4f * (1.0f - share) * v;
      tile.pigment(c)[cell] += 0.2f * v;
      dry.pigment_mm[k] = 0.01f * share;
    }
    canvas.dry_layers()[0].tiles.push_back(std::move(dry));
  }
  return canvas;
}

render::RenderSettings settings_for(const BenchRenderArgs& args, int threads) {
  render::RenderSettings settings;
  if (args.wavelengths == "full") {
    settings.wavelengths = 0;
  } else {
    std::size_t used = 0;
    try {
      settings.wavelengths = std::stoi(args.wavelengths, &used);
    } catch (const std::exception&) {
    }
    if (used == 0 || used != args.wavelengths.size() || settings.wavelengths < 1 ||
        settings.wavelengths > render::kMaxNodes) {
      throw std::runtime_error("--wavelengths " + args.wavelengths + ": expected 1..16 or full");
    }
  }
  settings.node_weights = render::parse_node_weights(args.weights);
  settings.threads = threads;
  render::validate(settings);
  return settings;
}

struct Timing {
  int threads = 0;
  std::vector<double> relight_ms;
  std::vector<double> cpu_ms;  // process CPU time of each relight
};

void run(const BenchRenderArgs& args) {
  const CanvasSize size = args.size.value_or(CanvasSize{4096, 4096});
  const int width = size.width, height = size.height;
  std::unique_ptr<paintcore::Painting> file;
  paintcore::Canvas synthetic({1, 1, 150.0, 1});
  std::vector<std::string> slots = kSlots;
  double load_ms = 0.0;  // reading the painting file (0: synthetic)
  if (!args.painting.empty()) {
    const auto load_start = Clock::now();
    file = std::make_unique<paintcore::Painting>(paintcore::Painting::load(args.painting));
    load_ms = ms_since(load_start);
    slots = file->pigment_slots();
  } else {
    synthetic = synthetic_canvas(width, height);
  }
  const paintcore::Canvas& canvas = file ? file->canvas() : synthetic;
  render::check_render_memory(canvas, "bench render");
  const double cells = static_cast<double>(canvas.width_cells()) * canvas.height_cells();
  int painted = 0;
  for (int t = 0; t < canvas.tile_count(); ++t) painted += canvas.tile(t) != nullptr;
  const int all_threads =
      args.threads > 0 ? args.threads : static_cast<int>(std::thread::hardware_concurrency());

  // The first render: palette (and rule) for D65, every tile baked and shaded.
  render::RenderSettings settings = settings_for(args, all_threads);
  auto start = Clock::now();
  render::TileRenderer renderer(settings, file ? render::SpectralPalette(settings, *file)
                                               : render::SpectralPalette(settings, slots));
  const double palette_ms = ms_since(start);
  renderer.use_reference_kernels(args.reference);
  start = Clock::now();
  renderer.render_all(canvas);
  const double first_ms = ms_since(start);

  // Relights: the light alternates between A and D65 (palettes built beforehand, so only the
  // renderer is timed), with one thread and with all.
  std::vector<Timing> timings;
  for (int threads : {1, all_threads}) {
    if (!timings.empty() && threads == timings.front().threads) break;
    Timing timing{threads, {}, {}};
    std::vector<render::SpectralPalette> palettes;
    std::vector<render::RenderSettings> lights;
    for (const char* light : {"A", "D65"}) {
      render::RenderSettings lit = settings_for(args, threads);
      lit.light = light;
      palettes.push_back(file ? render::SpectralPalette(lit, *file)
                              : render::SpectralPalette(lit, slots));
      lights.push_back(lit);
    }
    for (int run = 0; run < args.runs; ++run) {
      const auto which = static_cast<std::size_t>(run % 2);
      renderer.set_settings(lights[which], palettes[which]);
      start = Clock::now();
      const double cpu_start = process_cpu_ms();
      renderer.render_all(canvas);
      timing.relight_ms.push_back(ms_since(start));
      timing.cpu_ms.push_back(process_cpu_ms() - cpu_start);
    }
    timings.push_back(std::move(timing));
  }

  // The image out: gathered from the tiles, then encoded to PNG in memory.
  start = Clock::now();
  const render::Image image = renderer.image();
  const double image_ms = ms_since(start);
  start = Clock::now();
  const std::string png = render::encode_png(image, all_threads);
  const double png_ms = ms_since(start);

  const double relight_1 = util::median(timings.front().relight_ms);
  const double relight_n = util::median(timings.back().relight_ms);
  const double ns_per_cell = relight_1 * 1e6 / cells;
  const double scaling = relight_1 / relight_n;
  // The share of the relight's wall time × threads that the threads spent working.
  const double busy = util::median(timings.back().cpu_ms) / (relight_n * timings.back().threads);
  if (args.json) {
    nlohmann::json row{{"width", canvas.width_cells()},
                       {"height", canvas.height_cells()},
                       {"painted_tiles", painted},
                       {"tiles", canvas.tile_count()},
                       {"nodes", renderer.palette().nodes()},
                       {"weights", args.weights},
                       {"kernels", args.reference ? "reference" : "simd"},
                       {"load_ms", load_ms},
                       {"palette_ms", palette_ms},
                       {"first_render_ms", first_ms},
                       {"relight_ms", relight_n},
                       {"relight_1_thread_ms", relight_1},
                       {"threads", timings.back().threads},
                       {"thread_scaling", scaling},
                       {"relight_cpu_ms", util::median(timings.back().cpu_ms)},
                       {"relight_1_thread_cpu_ms", util::median(timings.front().cpu_ms)},
                       {"thread_busy", busy},
                       {"ns_per_cell", ns_per_cell},
                       {"image_ms", image_ms},
                       {"png_ms", png_ms},
                       {"png_bytes", png.size()},
                       {"runs", args.runs}};
    for (const Timing& t : timings)
      row["relight_runs_ms"][std::to_string(t.threads)] = t.relight_ms;
    std::cout << row.dump() << "\n";
    return;
  }
  std::printf("%dx%d cells, %d of %d tiles painted, %d nodes (%s), %s kernels\n",
              canvas.width_cells(), canvas.height_cells(), painted, canvas.tile_count(),
              renderer.palette().nodes(), args.weights.c_str(),
              args.reference ? "scalar reference" : "SIMD");
  if (file) std::printf("painting file load        %9.1f ms\n", load_ms);
  std::printf("palette for D65           %9.1f ms\n", palette_ms);
  std::printf("first render (%d threads)  %9.1f ms\n", all_threads, first_ms);
  for (const Timing& t : timings) {
    std::printf("relight, %d thread%s        %9.1f ms (median of %d; CPU %.1f ms)\n", t.threads,
                t.threads == 1 ? " " : "s", util::median(t.relight_ms), args.runs,
                util::median(t.cpu_ms));
  }
  std::printf("ns per cell (1 thread)     %9.1f\n", ns_per_cell);
  std::printf("thread scaling 1 -> %d     %9.2fx (threads busy %.0f %% of the relight)\n",
              timings.back().threads, scaling, 100.0 * busy);
  std::printf("image from tiles           %9.1f ms\n", image_ms);
  std::printf("PNG encode (%d threads)    %9.1f ms (%.1f MB)\n", all_threads, png_ms,
              static_cast<double>(png.size()) / 1e6);
}

const CommandRegistrar registrar("bench render", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  auto args = std::make_shared<BenchRenderArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "render", "Whole-canvas render: first render, relight with 1 and all threads, PNG encode");
  cmd->add_option("painting", args->painting,
                  "A .impasto painting (default: a synthetic one of --size)");
  add_size_option(*cmd, args->size, "the synthetic canvas (default 4096x4096)");
  cmd->add_option("--wavelengths", args->wavelengths, "Nodes 1..16, or full")
      ->capture_default_str();
  cmd->add_option("--weights", args->weights, "Nodes and XYZ weights")
      ->check(CLI::IsMember(util::names_of(render::kNodeWeightsNames)))
      ->capture_default_str();
  cmd->add_option("--runs", args->runs, "Relights per thread count (the median is reported)")
      ->check(finite_range(1, 100))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "The many-thread case (0: all cores)")
      ->check(finite_range(0, 1024));
  cmd->add_flag("--reference", args->reference,
                "The scalar per-cell reference code, shading recomputed every time (the "
                "renderer as it was before the spectral kernels)");
  cmd->add_flag("--json", args->json,
                "One JSON object: relight_ms, relight_1_thread_ms, ns_per_cell, thread_scaling, "
                "first_render_ms, palette_ms, png_ms, ...");
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_render_cmd
