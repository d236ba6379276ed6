// Cracks in the CPU reference renderer: the far-view blend of Gouffe's apparent reflectance
// into cracked cells, against its closed form; nothing changes where there is no crack.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render/tile_renderer.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr std::uint8_t kSpherePit = 3, kVGroove = 1;

std::vector<data::Pigment> test_pigments() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Black"), db.get("Red")};
}

// Matte and linear: a flat cell's pixel is linear in its reflectance.
RenderSettings linear_matte() {
  RenderSettings settings;
  settings.dry_material = {0.0f, 10.0f};
  settings.wet_material = {0.0f, 10.0f};
  settings.display = DisplayEncoding::linear_srgb;
  // The Gaussian rule: a cracked tile takes the scalar path and a plain one the kernels,
  // which agree bit for bit in uncracked cells with its weights (with the optimised rule's
  // they differ by float ulps, as spectral_kernels_test.cpp allows).
  settings.node_weights = NodeWeights::interpolatory;
  // The cavity's reflectance as the model gives it: no paint surface over it (with the
  // Saunderson correction, on by default, a black cavity shows k1 and the two paths' float
  // divisions differ by ulps).
  settings.saunderson = false;
  return settings;
}

// A grey ground of reflectance `g` at every wavelength.
SpectralPalette grey_palette(const RenderSettings& settings, double g) {
  return SpectralPalette(settings, data::light_from_spec("D65"), test_pigments(),
                         data::Spectrum{"grey", {300.0, 900.0}, {g, g}});
}

// A flat 3x2-tile canvas (0.1 mm cells): wet red paint over the left of tile 0, a dry black
// glaze over tile 4.
paintcore::Canvas painted_canvas() {
  paintcore::Canvas canvas({3 * kTileSize, 2 * kTileSize - 10, 254.0, 0});
  paintcore::Tile& tile = canvas.ensure_tile(0, 3);
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = 0; x < 20; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      tile.wet_volume_mm[c] = 0.05f;
      tile.pigment(2)[c] = 0.01f;
      tile.pigment(0)[c] = 0.01f;
    }
  }
  paintcore::DryTile dry;
  dry.tile_index = 4;
  dry.volume_mm.assign(kTileCells, 0.02f);
  dry.slots = {1};
  dry.pigment_mm.assign(kTileCells, 0.001f);
  canvas.dry_layers().push_back({{dry}});
  canvas.ensure_tile(4, 3).dry_height_mm.fill(0.02f);
  return canvas;
}

void set_crack(paintcore::Canvas& canvas, int x, int y, paintcore::CrackRecord record) {
  const int index = (y / kTileSize) * canvas.tiles_x() + x / kTileSize;
  canvas.cracks()
      .ensure_tile(index)
      .cells[static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize)] = record;
}

Image render_canvas(const paintcore::Canvas& canvas, const RenderSettings& settings,
                    double ground) {
  TileRenderer renderer(settings, grey_palette(settings, ground));
  renderer.render_all(canvas);
  return renderer.image();
}

float brightness(const Image& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return p[0] + p[1] + p[2];
}

}  // namespace

TEST(CrackRender, AnUncrackedCanvasRendersBitIdenticallyWithTheEffectOnOrOff) {
  const paintcore::Canvas canvas = painted_canvas();
  RenderSettings on = linear_matte(), off = linear_matte();
  on.display = off.display = DisplayEncoding::srgb;
  on.dry_material = off.dry_material = {0.2f, 20.0f};
  off.cracks = false;
  const Image a = render_canvas(canvas, on, 0.8);
  const Image b = render_canvas(canvas, off, 0.8);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_EQ(a.rgb, b.rgb);
}

TEST(CrackRender, ACrackedCanvasIsDarkerExactlyInItsCrackedCells) {
  RenderSettings settings = linear_matte();
  settings.display = DisplayEncoding::srgb;
  settings.dry_material = {0.2f, 20.0f};  // gloss and sRGB too: the blend is in reflectance
  const paintcore::Canvas plain = painted_canvas();
  paintcore::Canvas cracked = painted_canvas();
  // A diagonal V groove across tiles 0 and 1 (bare ground) and 4 (its walls the dry glaze),
  // and a pit in tile 2; tiles 3 and 5 stay uncracked. (A crack through dark paint to a
  // bright ground is brighter, as it should be: WallsShowTheLayerTheyExpose.)
  std::vector<std::pair<int, int>> cells;
  for (int i = 0; i < 90; ++i) cells.emplace_back(25 + i, 10 + i * 2 / 3);
  cells.emplace_back(150, 30);
  for (auto [x, y] : cells) {
    const bool pit = x == 150;
    const std::uint8_t walls = y >= kTileSize ? 0 : paintcore::kCrackExposesGround;
    set_crack(cracked, x, y, {0.15f, 0.03f, pit ? kSpherePit : kVGroove, walls});
  }
  const Image a = render_canvas(plain, settings, 0.8);
  const Image b = render_canvas(cracked, settings, 0.8);
  std::vector<std::uint8_t> is_crack(static_cast<std::size_t>(a.width * a.height), 0);
  for (auto [x, y] : cells) is_crack[static_cast<std::size_t>(y * a.width + x)] = 1;
  int darker = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (is_crack[static_cast<std::size_t>(y * a.width + x)]) {
        EXPECT_LT(brightness(b, x, y), brightness(a, x, y)) << x << "," << y;
        darker += brightness(b, x, y) < brightness(a, x, y);
      } else {
        // Unchanged: a tile with cracks is shaded cell by cell by the scalar reference, the
        // others by the spectral kernels, which sum 16 nodes in another order (float ulps).
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_NEAR(a.pixel(x, y)[ch], b.pixel(x, y)[ch], 1e-6f) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(darker, static_cast<int>(cells.size()));
}

TEST(CrackRender, ThePitBlendFollowsGouffesClosedForm) {
  // On a grey ground g, a sphere pit (F = G = R^2/(R^2+L^2), exact) covering c = pi R^2 /
  // cell^2 scales the flat cell's linear pixel by (1 - c) + c rho / g. The renderer's model
  // (closed form plus the measured table's difference) agrees with it to the table's Monte
  // Carlo noise, |d rho| <= 0.002 for the sphere.
  const RenderSettings settings = linear_matte();
  const double g = 0.7, cell = 0.1, R = 0.04;
  for (double L : {0.004, 0.04, 0.2, 2.0}) {
    paintcore::Canvas canvas = painted_canvas();
    set_crack(canvas, 100, 20, {static_cast<float>(L), static_cast<float>(R), kSpherePit, 0xFF});
    const Image image = render_canvas(canvas, settings, g);
    const double F = R * R / (R * R + L * L), G = F;
    const double rho = g * F + g * g * (1 - F) * G / (1 - g * (1 - G));
    const double c = std::numbers::pi * R * R / (cell * cell);
    const double expected = (1 - c) + c * rho / g;
    for (int ch = 0; ch < 3; ++ch) {
      const double ratio = image.pixel(100, 20)[ch] / image.pixel(101, 20)[ch];
      EXPECT_NEAR(ratio, expected, c * 0.002 / g + 2e-6) << "L = " << L << " channel " << ch;
    }
  }
}

TEST(CrackRender, ShallowCracksVanishAndDeepOnesGoBlack) {
  const RenderSettings settings = linear_matte();
  paintcore::Canvas canvas = painted_canvas();
  // A groove as wide as the cell (c = 1): its pixel is the cavity's alone.
  set_crack(canvas, 100, 20, {1e-6f, 0.05f, kVGroove, 0xFF});
  set_crack(canvas, 110, 20, {5000.0f, 0.05f, kVGroove, 0xFF});
  const Image image = render_canvas(canvas, settings, 0.8);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(image.pixel(100, 20)[ch], image.pixel(101, 20)[ch], 1e-5);  // L -> 0: rho -> rho0
    EXPECT_LT(image.pixel(110, 20)[ch], 2e-3 * image.pixel(101, 20)[ch]);   // L -> inf: black
  }
}

TEST(CrackRender, DeeperCracksAreDarker) {
  const RenderSettings settings = linear_matte();
  paintcore::Canvas canvas = painted_canvas();
  const float depths[] = {0.01f, 0.03f, 0.1f, 0.3f, 1.0f};
  for (int k = 0; k < 5; ++k) {
    set_crack(canvas, 10, 70 + 4 * k, {depths[k], 0.02f, kVGroove, 0xFF});  // bare ground
    set_crack(canvas, 100, 70 + 4 * k, {depths[k], 0.02f, kVGroove, 0});    // dry glaze
    set_crack(canvas, 12, 5 + 4 * k, {depths[k], 0.02f, kVGroove, 0xFF});   // wet paint
  }
  const Image image = render_canvas(canvas, settings, 0.8);
  for (int k = 1; k < 5; ++k) {
    EXPECT_LT(brightness(image, 10, 70 + 4 * k), brightness(image, 10, 70 + 4 * (k - 1)));
    EXPECT_LT(brightness(image, 100, 70 + 4 * k), brightness(image, 100, 70 + 4 * (k - 1)));
    EXPECT_LT(brightness(image, 12, 5 + 4 * k), brightness(image, 12, 5 + 4 * (k - 1)));
  }
}

TEST(CrackRender, WallsShowTheLayerTheyExpose) {
  // Under a dark glaze, a crack through to the bright ground is brighter than one whose walls
  // are the glaze.
  const RenderSettings settings = linear_matte();
  paintcore::Canvas canvas = painted_canvas();
  set_crack(canvas, 100, 80, {0.02f, 0.02f, kVGroove, paintcore::kCrackExposesGround});
  set_crack(canvas, 100, 90, {0.02f, 0.02f, kVGroove, 0});
  const Image image = render_canvas(canvas, settings, 0.9);
  EXPECT_GT(brightness(image, 100, 80), brightness(image, 101, 80));  // brighter than the glaze
  EXPECT_LT(brightness(image, 100, 90), brightness(image, 101, 90));  // darker than the glaze
}

TEST(CrackRender, SetCracksOnAPaintingUpdatesOnlyTheCrackedTiles) {
  const RenderSettings settings = linear_matte();
  paintcore::Painting painting({3 * kTileSize, 2 * kTileSize, 254.0, 3}, 1);
  TileRenderer renderer(settings, grey_palette(settings, 0.8));
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  renderer.update(painting.canvas(), paintcore::tile_indices(painting.take_changes(changes)));
  paintcore::CrackLayer cracks;
  cracks.ensure_tile(4).cells[300] = {0.1f, 0.02f, kVGroove, 0xFF};
  painting.set_cracks(std::move(cracks));
  const std::vector<int> dirty = paintcore::tile_indices(painting.take_changes(changes));
  EXPECT_EQ(dirty, std::vector<int>{4});
  const RenderStats stats = renderer.update(painting.canvas(), dirty);
  EXPECT_EQ(stats.tiles_shaded, 1);
  TileRenderer fresh(settings, grey_palette(settings, 0.8));
  fresh.render_all(painting.canvas());
  EXPECT_EQ(renderer.image().rgb, fresh.image().rgb);
}

TEST(CrackRender, OpticsForTheGpuAreThoseOfTheLibrary) {
  const CrackOptics none = crack_optics({}, 0.1);
  EXPECT_EQ(none.coverage, 0.0f);
  const CrackOptics pit = crack_optics({0.04f, 0.04f, kSpherePit, 0xFF}, 0.1);
  EXPECT_NEAR(pit.F, 0.5, 1e-6);
  EXPECT_NEAR(pit.G, 0.5, 1e-6);
  EXPECT_NEAR(pit.coverage, std::numbers::pi * 0.16, 1e-6);
  EXPECT_TRUE(pit.exposes_ground);
  const CrackOptics groove = crack_optics({0.04f, 0.03f, kVGroove, 2}, 0.1);
  EXPECT_NEAR(groove.F, 0.6, 1e-6);  // R / sqrt(R^2 + L^2)
  EXPECT_NEAR(groove.coverage, 0.6, 1e-6);
  EXPECT_FALSE(groove.exposes_ground);
}
