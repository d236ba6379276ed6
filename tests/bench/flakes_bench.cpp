// Cost of sparkles per cell (one per pixel at 100 % zoom): a tile full of flake paint under
// the sun, and the same tile without flakes, which must cost next to nothing.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "impasto/data/data_dir.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/flakes/flake_file.hpp"
#include "impasto/flakes/sparkles.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace {

using namespace impasto::flakes;

constexpr int kTile = 128;
const std::vector<double> kNodes{430.0, 470.0, 510.0, 550.0, 590.0, 630.0, 670.0, 710.0};

const SparkleRenderer& renderer() {
  static const SparkleRenderer r(
      load_flake_paint(impasto::data::data_dir() / "flakes" / "aluminium_flakes.flake"), kNodes);
  return r;
}

void sparkle_tile(benchmark::State& state, float concentration) {
  const std::size_t cells = kTile * kTile;
  std::vector<float> c(cells, concentration), thickness(cells, 0.05f), normals;
  for (int y = 0; y < kTile; ++y) {
    for (int x = 0; x < kTile; ++x) {
      const Vec3 n = normalized(Vec3{0.05 * std::sin(0.3 * x), 0.05 * std::cos(0.2 * y), 1});
      normals.insert(normals.end(), {float(n.x), float(n.y), float(n.z)});
    }
  }
  const FlakeTile tile{.first_ix = 0,
                       .first_iy = 0,
                       .width = kTile,
                       .height = kTile,
                       .cell_size_mm = 0.1,
                       .concentration = c,
                       .thickness_mm = thickness,
                       .surface_height_mm = {},
                       .normals = normals};
  Light sun;
  const double polar = 30 * std::numbers::pi / 180;
  sun.direction = {-std::sin(polar), 0, -std::cos(polar)};
  sun.spectral.assign(kNodes.size(), 1.0);
  const Light lights[] = {sun};
  View view;
  view.direction = normalized(Vec3{-0.3, 0.1, 1});
  std::vector<float> out(cells * kNodes.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderer().add_tile(tile, lights, view, out));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * cells));
  // A rate of 1e-9 × cells per second, inverted: nanoseconds per cell.
  state.counters["ns_per_cell"] =
      benchmark::Counter(1e-9 * static_cast<double>(state.iterations() * cells),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_FlakesOn(benchmark::State& state) {
  sparkle_tile(state, 1.0f);
}
void BM_FlakesOff(benchmark::State& state) {
  sparkle_tile(state, 0.0f);
}

// The whole tile renderer, one thread, 2 × 2 tiles of 0.5 mm wet paint over a woven canvas
// (16,384 cells, 8 nodes, the sun at 45°): the full per-cell cost with the flake hook.
enum class Scene { plain_palette, plain_paint, flake_paint };

void render_canvas(benchmark::State& state, Scene scene) {
  namespace render = impasto::render;
  namespace paintcore = impasto::paintcore;
  const auto& db = impasto::data::PigmentDatabase::defaults();
  std::vector<impasto::data::Pigment> pigments{db.get("White"), db.get("Blue Red Shade")};
  if (scene != Scene::plain_palette) pigments.push_back(db.get("Aluminium Metallic"));
  render::RenderSettings settings;
  settings.threads = 1;
  settings.light_elevation_deg = 45.0;
  const render::SpectralPalette palette(settings, impasto::data::light_from_spec(settings.light),
                                        pigments, render::hiding_reflectance(pigments[0]));
  paintcore::Canvas canvas({2 * paintcore::kTileSize, 2 * paintcore::kTileSize, 254.0, 7});
  const int slot = scene == Scene::flake_paint ? 2 : 1;
  for (int t = 0; t < canvas.tile_count(); ++t) {
    paintcore::Tile& tile = canvas.ensure_tile(t, static_cast<int>(pigments.size()));
    for (int c = 0; c < paintcore::kTileCells; ++c) {
      tile.wet_volume_mm[c] = 0.5f;
      tile.pigment(0)[c] = 0.25f;
      tile.pigment(slot)[c] = 0.25f;
    }
  }
  render::TileRenderer renderer(settings, palette);
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderer.render_all(canvas));
    benchmark::ClobberMemory();
  }
  const auto cells = static_cast<int64_t>(canvas.width_cells()) * canvas.height_cells();
  state.counters["ns_per_cell"] =
      benchmark::Counter(1e-9 * static_cast<double>(state.iterations() * cells),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_RenderNoFlakePigments(benchmark::State& state) {
  render_canvas(state, Scene::plain_palette);
}
void BM_RenderFlakePaletteWithoutFlakePaint(benchmark::State& state) {
  render_canvas(state, Scene::plain_paint);
}
void BM_RenderFlakePaint(benchmark::State& state) {
  render_canvas(state, Scene::flake_paint);
}

}  // namespace

BENCHMARK(BM_FlakesOn)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FlakesOff)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RenderNoFlakePigments)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderFlakePaletteWithoutFlakePaint)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderFlakePaint)->Unit(benchmark::kMillisecond);
