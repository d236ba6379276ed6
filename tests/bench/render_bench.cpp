// Rendering cost: relighting a whole 4096×4096 painting (every tile re-baked and re-shaded)
// and re-shading one 64×64 tile after a stroke touched it, with the relief's shadows and
// occlusion on and off, on thin paint and on impasto 0.2–3 mm thick.
#include <benchmark/benchmark.h>

#include <impasto/data/lights.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace impasto;
using paintcore::kTileCells;
using paintcore::kTileSize;

const std::vector<std::string> kSlots{"White", "Blue Red Shade", "Yellow Oxide"};

// A painting covered everywhere: one dry layer and a wet layer of two pigments per tile.
paintcore::Canvas covered_canvas(int cells) {
  paintcore::Canvas canvas({cells, cells, 300.0, 1});
  for (int t = 0; t < canvas.tile_count(); ++t) {
    paintcore::Tile& tile = canvas.ensure_tile(t, 3);
    paintcore::DryTile dry;
    dry.tile_index = t;
    dry.volume_mm.assign(kTileCells, 0.05f);
    dry.slots = {0, 2};
    dry.pigment_mm.assign(2 * kTileCells, 0.02f);
    for (int c = 0; c < kTileCells; ++c) {
      const float wave = 0.1f + 0.05f * static_cast<float>((c * 7 + t) % 13) / 13.0f;
      tile.wet_volume_mm[static_cast<std::size_t>(c)] = wave;
      tile.pigment(0)[c] = 0.5f * wave;
      tile.pigment(1)[c] = 0.2f * wave;
      tile.dry_height_mm[static_cast<std::size_t>(c)] = 0.05f;
    }
    if (canvas.dry_layers().empty()) canvas.dry_layers().emplace_back();
    canvas.dry_layers()[0].tiles.push_back(std::move(dry));
  }
  return canvas;
}

// Ridges of paint 0.2–3 mm high, 1.4 mm apart, every tile: the shadow march's worst case
// (slopes steeper than the light, so marches run long before they can stop).
paintcore::Canvas impasto_canvas(int cells) {
  paintcore::Canvas canvas({cells, cells, 150.0, 1});
  for (int t = 0; t < canvas.tile_count(); ++t) {
    paintcore::Tile& tile = canvas.ensure_tile(t, 3);
    for (int c = 0; c < kTileCells; ++c) {
      const int x = c % kTileSize, y = c / kTileSize;
      const float ridge = 0.5f + 0.5f * static_cast<float>(std::sin(0.75 * x + 0.2 * y));
      const float v = 0.2f + 2.8f * ridge * ridge * ridge;
      tile.wet_volume_mm[static_cast<std::size_t>(c)] = v;
      tile.pigment(0)[c] = 0.5f * v;
      tile.pigment(2)[c] = 0.2f * v;
    }
  }
  return canvas;
}

render::RenderSettings settings_for(int nodes, bool half, int threads = 0, bool relief = true) {
  render::RenderSettings settings;
  settings.shadows = settings.occlusion = relief;
  settings.threads = threads;
  settings.wavelengths = nodes;
  settings.storage =
      half ? render::ReflectanceStorage::float16 : render::ReflectanceStorage::float32;
  return settings;
}

// Args: nodes, half storage (0/1), threads (0: all), relief (shadows and occlusion, 0/1).
// Each iteration switches the light, so every tile re-bakes and re-shades. With one thread,
// CPU time is the whole work even on a busy machine.
void BM_RelightPainting4096(benchmark::State& state) {
  const paintcore::Canvas canvas = covered_canvas(4096);
  render::RenderSettings settings =
      settings_for(static_cast<int>(state.range(0)), state.range(1),
                   static_cast<int>(state.range(2)), state.range(3) != 0);
  render::TileRenderer renderer(settings, kSlots);
  renderer.render_all(canvas);
  const char* lights[] = {"A", "D65"};
  int which = 0;
  std::vector<render::SpectralPalette> palettes;
  for (const char* light : lights) {
    settings.light = light;
    palettes.emplace_back(settings, kSlots);
  }
  for (auto _ : state) {
    settings.light = lights[which];
    renderer.set_settings(settings, palettes[static_cast<std::size_t>(which)]);
    which = 1 - which;
    benchmark::DoNotOptimize(renderer.render_all(canvas));
  }
  state.counters["cells"] = 4096.0 * 4096.0;
}
BENCHMARK(BM_RelightPainting4096)
    ->Args({8, 0, 0, 1})
    ->Args({8, 1, 0, 1})
    ->Args({8, 0, 1, 1})
    ->Args({8, 0, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2)
    ->UseRealTime();

// Args: nodes, relief (0/1), impasto (0: thin paint, 1: 0.2–3 mm ridges). A 3×3-tile
// painting; the middle tile changes and is re-shaded, with the rims of its neighbours whose
// normals, occlusion and shadows read it; its dry stack unchanged. One thread: CPU time is
// the whole cost.
void BM_ReshadeTile64(benchmark::State& state) {
  const paintcore::Canvas canvas =
      state.range(2) != 0 ? impasto_canvas(3 * kTileSize) : covered_canvas(3 * kTileSize);
  render::TileRenderer renderer(
      settings_for(static_cast<int>(state.range(0)), false, 1, state.range(1) != 0), kSlots);
  renderer.render_all(canvas);
  const int middle[] = {4};
  render::RenderStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(stats = renderer.update(canvas, middle));
  state.counters["cells"] = kTileCells;
  state.counters["rim_cells"] = stats.border_cells;
}
BENCHMARK(BM_ReshadeTile64)
    ->Args({3, 1, 0})
    ->Args({8, 1, 0})
    ->Args({16, 1, 0})
    ->Args({8, 0, 0})
    ->Args({8, 1, 1})
    ->Args({8, 0, 1})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
