// The craquelure generator: a connected, deterministic network sized by film and age.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "impasto/cracks/craquelure.hpp"

namespace impasto::cracks {
namespace {

std::vector<std::pair<int, int>> crack_cells(const CrackMap& map) {
  std::vector<std::pair<int, int>> cells;
  map.for_each_crack([&](int x, int y, const CrackCell&) { cells.push_back({x, y}); });
  return cells;
}

TEST(Craquelure, NetworkIsConnectedForManySeeds) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    CrackMap map(160, 120, 0.1);
    CraquelureSettings s;
    s.seed = seed;
    s.island_size_mm = 2.0;
    generate_craquelure(map, PaintFilm{}, s);
    EXPECT_GT(map.crack_cells(), 500u) << "seed " << seed;
    EXPECT_EQ(count_crack_networks(map), 1u) << "seed " << seed;
  }
}

TEST(Craquelure, SameSeedSameMapOtherSeedOtherMap) {
  CraquelureSettings s;
  s.island_size_mm = 1.5;
  CrackMap a(100, 90, 0.1), b(100, 90, 0.1), c(100, 90, 0.1);
  generate_craquelure(a, PaintFilm{}, s);
  generate_craquelure(b, PaintFilm{}, s);
  s.seed = 99;
  generate_craquelure(c, PaintFilm{}, s);
  EXPECT_EQ(crack_cells(a), crack_cells(b));
  EXPECT_NE(crack_cells(a), crack_cells(c));
}

TEST(Craquelure, IslandsAreClosedPolygons) {
  // Without jitter the islands are the squares of the site grid: cracks run along the grid
  // lines, and the cells in between stay whole.
  CrackMap map(100, 100, 0.1);
  CraquelureSettings s;
  s.jitter = 0.0;
  s.island_size_mm = 2.5;  // 25 cells
  s.width_variation = 0.0;
  generate_craquelure(map, PaintFilm{}, s);
  EXPECT_TRUE(map.at(24, 10).has_crack() || map.at(25, 10).has_crack());
  EXPECT_FALSE(map.at(12, 12).has_crack());
  EXPECT_EQ(count_crack_networks(map), 1u);
}

TEST(Craquelure, CracksGrowWithAgeAndThickness) {
  CraquelureSettings young, old;
  young.age_years = 20.0;
  old.age_years = 200.0;
  const CrackSize y = craquelure_crack_size(young, 0.2, 1.0);
  const CrackSize o = craquelure_crack_size(old, 0.2, 1.0);
  EXPECT_LT(y.depth_mm, o.depth_mm);
  EXPECT_LT(y.half_width_mm, o.half_width_mm);
  EXPECT_DOUBLE_EQ(o.depth_mm, 0.2);  // old cracks reach the ground
  EXPECT_LT(craquelure_crack_size(old, 0.1, 1.0).half_width_mm, o.half_width_mm);
  EXPECT_EQ(craquelure_crack_size(young, 0.2, 1.0).depth_mm, 0.2 * 20.0 / 80.0);
}

TEST(Craquelure, ExposedLayerFollowsTheDepth) {
  // Two dry layers of 0.1 mm each: a young crack (a quarter of the film deep) exposes the
  // top layer, an old one reaches the canvas ground. Unpainted cells do not crack.
  const int w = 80, h = 60;
  std::vector<float> bottom(w * h, 0.1f), top(w * h, 0.1f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < 10; ++x) bottom[y * w + x] = top[y * w + x] = 0.0f;
  }
  PaintFilm film;
  film.layer_thickness_mm = {bottom, top};
  CraquelureSettings s;
  s.island_size_mm = 1.0;
  s.age_years = 20.0;
  CrackMap young(w, h, 0.1);
  generate_craquelure(young, film, s);
  ASSERT_GT(young.crack_cells(), 0u);
  young.for_each_crack([&](int x, int, const CrackCell& c) {
    EXPECT_EQ(c.exposed_layer, 1);
    EXPECT_GE(x, 10);
  });
  s.age_years = 300.0;
  CrackMap old(w, h, 0.1);
  generate_craquelure(old, film, s);
  old.for_each_crack(
      [&](int, int, const CrackCell& c) { EXPECT_EQ(c.exposed_layer, kCanvasGround); });
}

TEST(Craquelure, BadSettingsAreRejected) {
  CrackMap map(10, 10, 0.1);
  CraquelureSettings s;
  s.island_size_mm = 0.0;
  EXPECT_THROW(generate_craquelure(map, PaintFilm{}, s), std::runtime_error);
  s = {};
  s.jitter = 1.5;
  EXPECT_THROW(generate_craquelure(map, PaintFilm{}, s), std::runtime_error);
  s = {};
  s.age_years = NAN;
  EXPECT_THROW(generate_craquelure(map, PaintFilm{}, s), std::runtime_error);
  std::vector<float> wrong(5, 0.1f);
  PaintFilm film;
  film.layer_thickness_mm = {wrong};
  EXPECT_THROW(generate_craquelure(map, film, CraquelureSettings{}), std::runtime_error);
}

}  // namespace
}  // namespace impasto::cracks
