// The close-up view of cracks: its cell mean against the far view's blend, the shading's
// orderings (deep bottoms dark, shadowed walls dark) and the cells it must leave alone.
#include "impasto/render/crack_close_up.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "impasto/cracks/cavity_look.hpp"
#include "impasto/cracks/gouffe.hpp"
#include "impasto/render/render_painting.hpp"

using namespace impasto;
using namespace impasto::render;

namespace {

constexpr double kCellMm = 1.0;

paintcore::CrackRecord crack(cracks::CavityShape shape, double depth_mm, double half_width_mm) {
  paintcore::CrackRecord r;
  r.depth_mm = static_cast<float>(depth_mm);
  r.half_width_mm = static_cast<float>(half_width_mm);
  r.shape = static_cast<std::uint8_t>(shape);
  return r;
}

// Light from azimuth az (radians from +x toward +y) at elevation el above the canvas.
CanvasVec direction(double az, double el) {
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

// One channel of a cell magnified P times.
std::vector<float> close_up(const paintcore::CrackRecord& record, int P, float surface, float wall,
                            const CloseUpLight& light, const CloseUpView& view = {},
                            bool along_x = false) {
  std::vector<float> out(static_cast<std::size_t>(P * P));
  const float s[1] = {surface}, w[1] = {wall};
  crack_close_up_cell(record, kCellMm, along_x, P, s, w, light, view, out);
  return out;
}

double mean(const std::vector<float>& v) {
  double sum = 0.0;
  for (float x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

// The far view's blend (docs/cracks.md): (1 - c) surface + c rho, with Gouffe's closed form.
double far_view(const paintcore::CrackRecord& r, float surface, float wall) {
  const cracks::CrackCell cell{r.depth_mm, r.half_width_mm,
                               static_cast<cracks::CavityShape>(r.shape), r.exposed_layer};
  const double c = cracks::crack_coverage(cell, kCellMm);
  const double rho =
      cracks::apparent_reflectance(wall, cracks::view_factors(cell.shape, cell.dims()));
  return (1.0 - c) * surface + c * rho;
}

}  // namespace

TEST(CrackCloseUp, CellWithoutCrackIsItsColourInEveryPixel) {
  const std::vector<float> surface = {0.2f, 0.5f, 0.9f};
  std::vector<float> out(3 * 8 * 8, -1.0f);
  crack_close_up_cell({}, kCellMm, true, 8, surface, surface, CloseUpLight{}, CloseUpView{}, out);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], surface[i % 3]);
}

// The close-up's cell mean against the far view's blend, view straight down, P = 48.
// Under a uniform sky the two differ only by Gouffe's uniform-wall assumption (the close-up
// shades every point with its own view factor) and the pixel grid's cover of the opening:
// measured worst 0.018 (cone pit L = 2R, box groove L = R/2) over L/R 0.1..4 and walls
// 0.2..0.9; tolerance 0.025. With the sun overhead as well, the eye looks along the light
// into the lit bottom (a hot spot the far view's hemispherical average does not have), so
// only shallow cavities agree: L <= R/4, worst 0.035 (box groove); tolerance 0.04.
void expect_cell_mean_near_far_view(const CloseUpLight& light, std::initializer_list<double> depths,
                                    double tolerance) {
  double worst = 0.0;
  for (cracks::CavityShape shape : cracks::kAllShapes) {
    for (double depth_over_R : depths) {
      for (float rho0 : {0.2f, 0.6f, 0.9f}) {
        const auto r = crack(shape, 0.25 * depth_over_R, 0.25);
        const double near = mean(close_up(r, 48, 0.7f, rho0, light));
        const double far = far_view(r, 0.7f, rho0);
        worst = std::max(worst, std::abs(near - far));
        EXPECT_NEAR(near, far, tolerance)
            << cracks::shape_name(shape) << " L/R " << depth_over_R << " rho0 " << rho0;
      }
    }
  }
  std::printf("close-up cell mean vs far blend (sky fraction %.2f): worst |difference| %.4f\n",
              light.sky_fraction, worst);
}

TEST(CrackCloseUp, CellMeanTendsToFarViewBlendUnderTheSky) {
  expect_cell_mean_near_far_view({{0, 0, 1}, 0.0046, 1.0, 1}, {0.1, 0.25, 0.5, 1.0, 2.0, 4.0},
                                 0.025);
}

TEST(CrackCloseUp, CellMeanTendsToFarViewBlendForShallowCracksUnderTheSun) {
  expect_cell_mean_near_far_view(CloseUpLight{}, {0.1, 0.25}, 0.04);
}

TEST(CrackCloseUp, DeepCrackBottomDarkerThanRim) {
  // A deep V groove across x (L = 4R) under an overhead sun: every visible point gets the
  // same direct light, so only its view factor to the opening differs (small at the bottom).
  const int P = 64;
  const CloseUpLight sky_only{{0, 0, 1}, 0.0046, 1.0, 16};
  for (const CloseUpLight& light : {CloseUpLight{}, sky_only}) {
    const auto out = close_up(crack(cracks::CavityShape::VGroove, 1.0, 0.25), P, 0.7f, 0.5f, light);
    const auto row = static_cast<std::size_t>((P / 2) * P);
    const float bottom = out[row + P / 2];
    const float near_rim = out[row + P / 2 - P / 4 + 1];
    EXPECT_LT(bottom, near_rim);
    EXPECT_LT(near_rim, 0.5f);  // and darker than a flat wall of the same paint
  }
  // A deep cone pit under the sky: the apex darker than the wall by the rim.
  const auto out = close_up(crack(cracks::CavityShape::ConePit, 1.2, 0.3), P, 0.7f, 0.8f, sky_only);
  const auto row = static_cast<std::size_t>((P / 2) * P);
  EXPECT_LT(out[row + P / 2], out[row + P / 2 - 18]);
}

TEST(CrackCloseUp, ShadowedWallDarkerThanLitWallUnderLowLight) {
  // A V groove along y; the light low from +x: the wall facing +x (left, x < 0) is lit, the
  // other turned away and in the rim's shadow.
  const int P = 64;
  CloseUpLight light{direction(0.0, 20.0 * std::numbers::pi / 180.0), 0.05, 0.1, 16};
  const auto out = close_up(crack(cracks::CavityShape::VGroove, 0.25, 0.25), P, 0.7f, 0.8f, light);
  double left = 0.0, right = 0.0;
  for (int y = 0; y < P; ++y) {
    for (int d = 1; d < P / 4; ++d) {
      left += out[static_cast<std::size_t>(y * P + P / 2 - d)];
      right += out[static_cast<std::size_t>(y * P + P / 2 + d - 1)];
    }
  }
  EXPECT_GT(left, 1.5 * right);
}

TEST(CrackCloseUp, SoftShadowEdgeIsGradual) {
  // A box groove along y lit low from +x through a wide disc: across the bottom, between
  // the lit side and the shadowed one, the light falls through values strictly between.
  const int P = 64;
  CloseUpLight light{direction(0.0, 45.0 * std::numbers::pi / 180.0), 0.15, 0.0, 64};
  const auto out =
      close_up(crack(cracks::CavityShape::BoxGroove, 0.25, 0.25), P, 0.7f, 0.8f, light);
  const auto row = std::vector<float>(out.begin() + (P / 2) * P, out.begin() + (P / 2 + 1) * P);
  // The bottom left of the centre sees the light past the right rim; the right half is shaded.
  const float hi = row[static_cast<std::size_t>(P / 2 - P / 4 + 1)];
  const float lo = row[static_cast<std::size_t>(P / 2 + P / 4 - 2)];
  int between = 0;
  for (int x = P / 2 - P / 4 + 1; x < P / 2 + P / 4 - 1; ++x) {
    const float v = row[static_cast<std::size_t>(x)];
    if (v > lo + 1e-4f && v < hi - 1e-4f) ++between;
  }
  EXPECT_LT(lo, hi);
  EXPECT_GE(between, 2);
}

TEST(CrackCloseUp, FiniteEverywhere) {
  const std::vector<CanvasVec> lights = {direction(0.3, 1.5), direction(2.0, 0.05),
                                         direction(4.0, -0.3)};
  const std::vector<CanvasVec> views = {{0, 0, 1}, direction(1.0, 0.3)};
  for (cracks::CavityShape shape : cracks::kAllShapes) {
    for (double depth : {1e-4, 0.3, 20.0}) {
      for (const CanvasVec& l : lights) {
        for (const CanvasVec& v : views) {
          const CloseUpLight light{l, 0.02, 0.25, 4};
          // No point gets more than the sky, the whole sun facing it and walls as bright as
          // white: rho0 (E_sky + E_sun + 1), E_sun = 0.75 / sin(elevation).
          const double bound = 0.9 * (1.25 + (l.z > 0.0 ? 0.75 / l.z : 0.0));
          for (bool along_x : {false, true}) {
            for (float x :
                 close_up(crack(shape, depth, 0.3), 12, 0.5f, 0.9f, light, {v}, along_x)) {
              ASSERT_TRUE(std::isfinite(x));
              ASSERT_GE(x, 0.0f);
              ASSERT_LE(x, bound);
            }
          }
        }
      }
    }
  }
}

TEST(CrackCloseUp, BadInputIsRefused) {
  std::vector<float> out(4);
  const float s[1] = {0.5f};
  const auto r = crack(cracks::CavityShape::SpherePit, 0.1, 0.1);
  EXPECT_THROW(crack_close_up_cell(r, kCellMm, true, 3, s, s, {}, {}, out), std::invalid_argument);
  std::vector<float> ok(9);
  EXPECT_THROW(crack_close_up_cell(r, kCellMm, true, 3, s, s, {}, {{0, 0, -1}}, ok),
               std::invalid_argument);
  EXPECT_THROW(crack_close_up_cell(r, kCellMm, true, 3, s, s, {{0, 0, 1}, 0.0, NAN, 4}, {}, ok),
               std::invalid_argument);
}

TEST(CrackCloseUp, RegionOfAPaintingMagnifiesItsCells) {
  paintcore::Canvas canvas({8, 6, 25.4, 0});
  Image colours{8, 6, std::vector<float>(3 * 8 * 6)};
  for (std::size_t i = 0; i < colours.rgb.size(); ++i) colours.rgb[i] = 0.01f * (i % 97);
  // One groove along x through cells (2..4, 3).
  auto& tile = canvas.cracks().ensure_tile(0);
  for (int x = 2; x <= 4; ++x) {
    tile.cells[static_cast<std::size_t>(3 * paintcore::kTileSize + x)] =
        crack(cracks::CavityShape::ArcGroove, 0.3, 0.2);
  }
  const int P = 4;
  const Image image = render_crack_close_up(canvas, colours, colours, {1, 2, 5, 3}, P, {}, {});
  ASSERT_EQ(image.width, 5 * P);
  ASSERT_EQ(image.height, 3 * P);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const int cx = 1 + x / P, cy = 2 + y / P;
      const bool cracked = cy == 3 && cx >= 2 && cx <= 4;
      // The groove runs along x: its opening is the cell's middle rows.
      const bool in_opening = cracked && (y % P == 1 || y % P == 2);
      for (int c = 0; c < 3; ++c) {
        if (in_opening) {
          EXPECT_NE(image.pixel(x, y)[c], colours.pixel(cx, cy)[c]) << x << "," << y;
        } else {
          EXPECT_EQ(image.pixel(x, y)[c], colours.pixel(cx, cy)[c]) << x << "," << y;
        }
      }
    }
  }
  EXPECT_THROW(render_crack_close_up(canvas, colours, colours, {4, 2, 5, 3}, P, {}, {}),
               std::runtime_error);
}

TEST(CrackCloseUp, PaintingWithoutCracksIsItsRenderMagnified) {
  const paintcore::Painting painting(paintcore::CanvasSpec{12, 10, 254.0, 7}, 1);
  RenderSettings settings;
  settings.display = DisplayEncoding::linear_srgb;
  settings.threads = 1;
  const Image plain = render_painting(painting, settings);
  const int P = 3;
  const Image close = render_painting_close_up(painting, settings, {2, 1, 6, 5}, P);
  ASSERT_EQ(close.width, 6 * P);
  ASSERT_EQ(close.height, 5 * P);
  for (int y = 0; y < close.height; ++y) {
    for (int x = 0; x < close.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(close.pixel(x, y)[c], plain.pixel(2 + x / P, 1 + y / P)[c]);
      }
    }
  }
}

TEST(CrackCloseUp, RegionTextIsParsedOrRefused) {
  const CellRegion r = parse_cell_region("3,4,10,20");
  EXPECT_EQ(r.x, 3);
  EXPECT_EQ(r.y, 4);
  EXPECT_EQ(r.w, 10);
  EXPECT_EQ(r.h, 20);
  for (const char* bad : {"", "1,2,3", "1,2,3,4,5", "1,2,x,4", "1, 2,3,4", "1,2,3,4 "}) {
    EXPECT_THROW(parse_cell_region(bad), std::runtime_error) << bad;
  }
  // Beyond a canvas's reach (x + w would overflow an int): refused naming the field.
  try {
    parse_cell_region("2147483647,0,10,10", "--crop");
    ADD_FAILURE() << "an x of 2^31 - 1 was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "--crop 2147483647,0,10,10: X 2147483647 is outside -131072..131072");
  }
  EXPECT_THROW(parse_cell_region("0,0,0,5"), std::runtime_error);
}
