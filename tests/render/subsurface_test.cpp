// The subsurface spread (subsurface.hpp): its kernel keeps the light it spreads and collapses
// to the K-M colour where the diffusion length is far below a cell; the spread softens an
// edge without changing the total; thin layers cost nothing.
#include "impasto/render/subsurface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "three_pigment_palette.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr double kCellMm = 0.1;

double kernel_sum(const SpreadKernel& k) {
  return std::accumulate(k.weights.begin(), k.weights.end(), 0.0);
}

RenderSettings ghs_linear() {
  RenderSettings s;
  s.display = DisplayEncoding::linear_srgb;
  s.surface.model = SurfaceModel::ghs;
  return s;
}

}  // namespace

void expect_a_proper_kernel(const SpreadKernel& k) {
  EXPECT_NEAR(kernel_sum(k), 1.0, 1e-5);
  for (float w : k.weights) EXPECT_GE(w, 0.0f);
  for (int d = 1; d <= k.radius; ++d) {  // isotropic
    EXPECT_FLOAT_EQ(k.at(d, 0), k.at(0, -d));
    EXPECT_FLOAT_EQ(k.at(-d, d), k.at(d, -d));
  }
}

TEST(Subsurface, ScatteringPaintSpreadsByTheDipoleAndCollapsesBelowACell) {
  // Lighter absorption, longer diffusion length: less light stays in its cell.
  double last_centre = 1.0;
  for (double k : {1.0, 0.1, 0.01, 0.001}) {
    const dipole::Medium medium = dipole::from_kubelka_munk(k, 1.0, 0.005);
    ASSERT_FALSE(is_clear_layer(medium, 1.0));
    const SpreadKernel kernel = spread_kernel(medium, 1.0, kCellMm);
    expect_a_proper_kernel(kernel);
    EXPECT_LE(kernel.at(0, 0), last_centre + 1e-6) << "K " << k;
    last_centre = kernel.at(0, 0);
  }
  EXPECT_LT(last_centre, 0.98f);
  // Far below a cell (dense, absorbing paint): the single weight 1, the K-M colour.
  const dipole::Medium dense = dipole::from_kubelka_munk(20.0, 5.0, 0.005);
  EXPECT_LT(spread_length_mm(dense, 1.0), 0.01 * kCellMm);
  const SpreadKernel tiny = spread_kernel(dense, 1.0, kCellMm);
  EXPECT_EQ(tiny.radius, 0);
  EXPECT_EQ(tiny.at(0, 0), 1.0f);
}

TEST(Subsurface, ClearGlazeSpreadsByItsThickness) {
  const dipole::Medium glaze = dipole::from_kubelka_munk(0.2, 0.005, 0.005);
  double last_centre = 1.0;
  for (double thickness : {0.005, 0.05, 0.1, 0.2, 0.4}) {
    ASSERT_TRUE(is_clear_layer(glaze, thickness));
    EXPECT_EQ(spread_length_mm(glaze, thickness), thickness);
    const SpreadKernel kernel = spread_kernel(glaze, thickness, kCellMm);
    expect_a_proper_kernel(kernel);
    EXPECT_LE(kernel.at(0, 0), last_centre + 1e-6) << thickness;
    last_centre = kernel.at(0, 0);
  }
  EXPECT_EQ(spread_kernel(glaze, 0.005, kCellMm).radius, 0);
  EXPECT_LT(last_centre, 0.5f);  // 0.4 mm of glaze over 0.1 mm cells: most light moves
}

TEST(Subsurface, SpreadSoftensAnEdgeAndKeepsTheTotal) {
  constexpr int kW = 24, kH = 9;
  Image body;
  body.width = kW;
  body.height = kH;
  body.rgb.assign(3 * kW * kH, 0.0f);
  for (int y = 0; y < kH; ++y) {
    for (int x = kW / 2; x < kW; ++x) {
      for (int c = 0; c < 3; ++c) body.pixel(x, y)[c] = 0.8f;
    }
  }
  SubsurfaceMap map;
  map.width = kW;
  map.height = kH;
  map.cell_mm = kCellMm;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      SpreadingCell cell;
      cell.x = x;
      cell.y = y;
      cell.medium.fill(dipole::from_kubelka_munk(0.05, 0.01, 0.005));  // a glaze
      cell.length_cells.fill(1.5f);
      cell.layer_mm = 0.15f;
      map.cells.push_back(cell);
    }
  }
  Image out = body;
  apply_spread(map, body, out);
  const double before = std::accumulate(body.rgb.begin(), body.rgb.end(), 0.0);
  const double after = std::accumulate(out.rgb.begin(), out.rgb.end(), 0.0);
  EXPECT_NEAR(after, before, 1e-4 * before);
  const int y = kH / 2;
  EXPECT_GT(out.pixel(kW / 2 - 1, y)[0], 0.005f);  // light crossed the edge
  EXPECT_LT(out.pixel(kW / 2, y)[0], 0.795f);
  EXPECT_NEAR(out.pixel(kW - 5, y)[0], 0.8f, 1e-4f);  // far from the edge: as before
}

TEST(Subsurface, OnlyLayersThatSpreadAreMappedAndNothingElseChanges) {
  // A thin glaze (0.01 mm < a quarter cell) maps nothing: the render is the ghs image itself.
  paintcore::Canvas canvas({kTileSize, kTileSize, 254.0, 3});
  paintcore::DryTile dry;
  dry.tile_index = 0;
  dry.volume_mm.assign(kTileCells, 0.01f);
  dry.slots = {2};
  dry.pigment_mm.assign(kTileCells, 0.001f);
  canvas.dry_layers().push_back({{dry}});
  const RenderSettings settings = ghs_linear();
  const SpectralPalette palette = make_palette(settings);
  SubsurfaceMap map;
  const Image spread = render_canvas_with_subsurface(canvas, palette, settings, &map);
  EXPECT_TRUE(map.cells.empty());
  TileRenderer renderer(settings, palette);
  renderer.render_all(canvas);
  EXPECT_EQ(spread.rgb, renderer.image().rgb);

  // A thick, weakly scattering glaze over half the canvas spreads; the other half does not.
  paintcore::Tile& tile = canvas.ensure_tile(0, 3);
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = 0; x < kTileSize / 2; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      tile.wet_volume_mm[c] = 0.2f;
      tile.pigment(2)[c] = 0.02f;
      tile.pigment(0)[c] = 0.001f;
    }
  }
  const SubsurfaceMap glazed = subsurface_map(canvas, palette, settings);
  ASSERT_FALSE(glazed.cells.empty());
  for (const SpreadingCell& cell : glazed.cells) EXPECT_LT(cell.x, kTileSize / 2);
  RenderSettings off = settings;
  off.surface.subsurface = false;
  EXPECT_TRUE(subsurface_map(canvas, palette, off).cells.empty());
}
