// The whole-tile entry point: no flakes, no work; the same input, the same sparkles; a small
// light move changes a minority; zooming out merges sparkles into the mean (Eq. 2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "flake_test_geometry.hpp"
#include "impasto/flakes/sparkles.hpp"
#include "test_paints.hpp"

namespace impasto::flakes {
namespace {

using test::direction;
using test::kDegree;
using test::kNodes;
using test::viewer;

Light sun_from(double polar_deg, double azimuth_deg = 0) {
  Light light;
  light.direction = -direction(polar_deg, azimuth_deg);
  light.spectral.assign(kNodes.size(), 1.0);
  return light;
}

// A square tile of flake paint, with a gently rippled surface.
struct TileData {
  int size;
  std::vector<float> concentration, thickness, normals;
  explicit TileData(int n, float c = 1.0f) : size(n) {
    concentration.assign(n * n, c);
    thickness.assign(n * n, 0.05f);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const Vec3 normal = normalized(Vec3{0.05 * std::sin(0.3 * x), 0.05 * std::cos(0.2 * y), 1});
        normals.insert(normals.end(), {float(normal.x), float(normal.y), float(normal.z)});
      }
    }
  }
  FlakeTile tile(double cell_mm = 0.1) const {
    return {.first_ix = 1000,
            .first_iy = -40,
            .width = size,
            .height = size,
            .cell_size_mm = cell_mm,
            .concentration = concentration,
            .thickness_mm = thickness,
            .surface_height_mm = {},
            .normals = normals};
  }
};

std::vector<float> render(const SparkleRenderer& r, const TileData& data, const Light& light,
                          double cell_mm = 0.1) {
  std::vector<float> out(data.concentration.size() * kNodes.size(), 0.0f);
  const Light lights[] = {light};
  r.add_tile(data.tile(cell_mm), lights, viewer(), out);
  return out;
}

TEST(SparkleTile, NoFlakesMeansNoWorkAndExactlyZero) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  const TileData empty(64, 0.0f);
  // Sentinel values show that nothing is written, not even a zero.
  std::vector<float> out(64 * 64 * kNodes.size(), std::numeric_limits<float>::quiet_NaN());
  out[5] = 7.0f;
  const Light lights[] = {sun_from(30)};
  EXPECT_EQ(r.add_tile(empty.tile(), lights, viewer(), out), 0u);
  EXPECT_EQ(out[5], 7.0f);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i != 5) {
      ASSERT_TRUE(std::isnan(out[i])) << i;
    }
  }
  // Cells without flakes inside a tile with flakes get exactly nothing added.
  TileData half(64);
  for (int i = 0; i < 64 * 32; ++i) half.concentration[i] = 0.0f;
  std::vector<float> mixed(64 * 64 * kNodes.size(), 0.0f);
  EXPECT_EQ(r.add_tile(half.tile(), lights, viewer(), mixed), 64u * 32u);
  for (int i = 0; i < 64 * 32 * 3; ++i) ASSERT_EQ(mixed[i], 0.0f);
}

TEST(SparkleTile, SameInputsSameSparkles) {
  const SparkleRenderer a(test::shipped_aluminium(), kNodes);
  const SparkleRenderer b(test::shipped_aluminium(), kNodes);
  const TileData data(96);
  const std::vector<float> first = render(a, data, sun_from(30));
  EXPECT_EQ(first, render(a, data, sun_from(30)));
  EXPECT_EQ(first, render(b, data, sun_from(30)));
  std::size_t lit = 0;
  for (float v : first) lit += v > 0.0f;
  EXPECT_GT(lit, 0u);
}

// Fraction of the cells sparkling in either image that differ between the two.
double changed_fraction(const std::vector<float>& a, const std::vector<float>& b) {
  std::size_t either = 0, changed = 0;
  for (std::size_t i = 0; i < a.size(); i += kNodes.size()) {
    if (a[i] > 0.0f || b[i] > 0.0f) {
      ++either;
      changed += (a[i] > 0.0f) != (b[i] > 0.0f);
    }
  }
  EXPECT_GT(either, 50u);
  return either ? double(changed) / double(either) : 0.0;
}

TEST(SparkleTile, ASmallLightMoveChangesOnlyAMinority) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  const TileData data(160);
  const std::vector<float> before = render(r, data, sun_from(30));
  const double small = changed_fraction(before, render(r, data, sun_from(30.03)));
  EXPECT_GT(small, 0.0);  // the sparkles do follow the light ...
  EXPECT_LT(small, 0.3);  // ... but most stay
  EXPECT_GT(changed_fraction(before, render(r, data, sun_from(35))), 0.9);  // a big move: new ones
}

TEST(SparkleTile, ZoomingOutMergesSparklesIntoTheMean) {
  // Eq. 2: averaging k × k cells divides the relative deviation by k, keeping the mean.
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  const TileData data(256);
  const std::vector<float> cells = render(r, data, sun_from(30), 0.25);
  auto coefficient_of_variation = [&](int k) {
    double sum = 0, sum2 = 0;
    const int blocks = 256 / k;
    for (int by = 0; by < blocks; ++by) {
      for (int bx = 0; bx < blocks; ++bx) {
        double block = 0;
        for (int y = 0; y < k; ++y) {
          for (int x = 0; x < k; ++x) block += cells[((by * k + y) * 256 + bx * k + x) * 3 + 1];
        }
        block /= k * k;
        sum += block;
        sum2 += block * block;
      }
    }
    const double n = blocks * blocks, mean = sum / n;
    return std::sqrt(sum2 / n - mean * mean) / mean;
  };
  const double one = coefficient_of_variation(1), eight = coefficient_of_variation(8);
  EXPECT_GT(one, 1.0);  // single cells: rare, bright points
  EXPECT_NEAR(one / eight, 8.0, 1.6);
  for (float v : cells) ASSERT_GE(v, 0.0f);  // never a dark point
}

TEST(SparkleTile, BadInputNamesTheCell) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  TileData data(8);
  data.concentration[8 * 2 + 3] = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> out(8 * 8 * kNodes.size());
  const Light lights[] = {sun_from(30)};
  try {
    r.add_tile(data.tile(), lights, viewer(), out);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("at cell (1003, -38)"), std::string::npos) << e.what();
  }
  data.concentration[8 * 2 + 3] = 1.0f;
  Light wrong = sun_from(30);
  wrong.spectral.resize(2);
  const Light wrong_lights[] = {wrong};
  EXPECT_THROW(r.add_tile(data.tile(), wrong_lights, viewer(), out), std::runtime_error);
  std::vector<float> short_out(5);
  EXPECT_THROW(r.add_tile(data.tile(), lights, viewer(), short_out), std::runtime_error);
}

}  // namespace
}  // namespace impasto::flakes
