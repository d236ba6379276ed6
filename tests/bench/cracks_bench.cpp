// Cost of the crack effect's pieces: the closed form per wavelength, the view factors per
// cell, a cell's spectrum, the Monte Carlo reference, the craquelure generator, and the
// renderer's crack hook on a whole canvas.
#include <benchmark/benchmark.h>

#include <vector>

#include "impasto/cracks/cavity_correction.hpp"
#include "impasto/cracks/cavity_look.hpp"
#include "impasto/cracks/crack_layer_maps.hpp"
#include "impasto/cracks/craquelure.hpp"
#include "impasto/cracks/gouffe.hpp"
#include "impasto/cracks/monte_carlo.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace {
using namespace impasto::cracks;

void BM_CracksApparentReflectance(benchmark::State& state) {
  const ViewFactors vf = view_factors(CavityShape::VGroove, {0.2, 0.04});
  double rho0 = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(apparent_reflectance(rho0, vf));
    rho0 = rho0 < 0.9 ? rho0 + 1e-3 : 0.1;
  }
}
BENCHMARK(BM_CracksApparentReflectance);

void BM_CracksViewFactors(benchmark::State& state) {
  const auto shape = static_cast<CavityShape>(state.range(0));
  double depth = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(view_factors(shape, {depth, 0.05}));
    depth = depth < 1.0 ? depth + 1e-3 : 0.1;
  }
  state.SetLabel(std::string(shape_name(shape)));
}
BENCHMARK(BM_CracksViewFactors)->DenseRange(0, 5);

// A cell's 16 wavelengths under the default scene's corrected model (blended once, as a
// render does).
void BM_CracksCellSpectrum16(benchmark::State& state) {
  const CrackCell cell{0.2f, 0.03f, CavityShape::VGroove, kCanvasGround};
  std::vector<float> surface(16, 0.7f), wall(16, 0.4f), out(16);
  const auto correction = cavity_correction({30.0, 0.25, true});
  for (auto _ : state) {
    crack_cell_reflectance(cell, 0.1, surface, wall, out, correction.get());
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_CracksCellSpectrum16);

// Blending the shipped tables for a new light (once per light the render sees).
void BM_CracksCorrectionForALight(benchmark::State& state) {
  double zenith = 10.0;
  for (auto _ : state) {
    const CavityCorrection correction({zenith, 0.25, true});
    benchmark::DoNotOptimize(correction.differences().data());
    zenith = zenith < 80.0 ? zenith + 1.0 : 10.0;
  }
}
BENCHMARK(BM_CracksCorrectionForALight)->Unit(benchmark::kMicrosecond);

void BM_CracksMonteCarloReference(benchmark::State& state) {
  MonteCarloSettings settings;
  settings.paths = 10000;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        trace_cavity(CavityShape::CylinderPit, {2.0, 1.0}, Illumination::diffuse(), settings));
  }
  state.SetItemsProcessed(state.iterations() * 10000);
}
BENCHMARK(BM_CracksMonteCarloReference)->Unit(benchmark::kMillisecond);

void BM_CracksCraquelure512(benchmark::State& state) {
  for (auto _ : state) {
    CrackMap map(512, 512, 0.1);
    generate_craquelure(map, PaintFilm{}, CraquelureSettings{});
    benchmark::DoNotOptimize(map.crack_cells());
  }
}
BENCHMARK(BM_CracksCraquelure512)->Unit(benchmark::kMillisecond);

// A 512 x 512-cell canvas (0.1 mm cells) under a uniform dry white film, rendered on one
// thread at 8 nodes: without cracks (0) and with a craquelure over all of it (1).
void BM_CracksRender512(benchmark::State& state) {
  using impasto::paintcore::kTileCells;
  impasto::paintcore::Canvas canvas({512, 512, 254.0, 1});
  impasto::paintcore::DryLayer layer;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    impasto::paintcore::DryTile dry;
    dry.tile_index = index;
    dry.volume_mm.assign(kTileCells, 0.2f);
    dry.slots = {0};
    dry.pigment_mm.assign(kTileCells, 0.1f);
    layer.tiles.push_back(std::move(dry));
    canvas.ensure_tile(index, 1).dry_height_mm.fill(0.2f);
  }
  canvas.dry_layers().push_back(std::move(layer));
  if (state.range(0) == 1) {
    CrackMap map(512, 512, canvas.cell_mm());
    generate_craquelure(map, PaintFilm{}, CraquelureSettings{});
    canvas.cracks() = to_crack_layer(map);
    state.SetLabel(std::to_string(map.crack_cells()) + " crack cells");
  }
  impasto::render::RenderSettings settings;
  settings.threads = 1;
  const std::vector<std::string> slots = {"White"};
  impasto::render::TileRenderer renderer(settings, slots);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render_all(canvas));
  state.SetItemsProcessed(state.iterations() * 512 * 512);
}
BENCHMARK(BM_CracksRender512)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
