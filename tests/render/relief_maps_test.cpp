// Export for 3D and print: the height map back in mm, the normal map of a known slope, and a
// render at 2x whose relief shades smoothly (relief_maps.hpp, Painting::refined).
#include "impasto/render/relief_maps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "impasto/render/render_painting.hpp"

using namespace impasto;

namespace {

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impasto_relief_maps_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

paintcore::Painting painted() {
  paintcore::Painting p({90, 60, 254.0, 2}, 1);
  p.set_brush(paintcore::BrushSettings{"round", 3.0, 0.5});
  p.load_brush({{"Red Oxide", 1.0}, {"White", 1.0}}, 40.0);
  p.begin_stroke();
  for (int i = 0; i < 20; ++i) {
    paintcore::PenSample s;
    s.x_mm = 1.0 + 0.35 * i;
    s.y_mm = 3.0 + 0.05 * i;
    s.pressure = 0.8f;
    s.buttons = paintcore::kPenTip;
    p.stroke_to(s);
  }
  p.end_stroke();
  return p;
}

TEST(ReliefMaps, HeightMapsGiveTheCanvasHeightsBack) {
  const paintcore::Painting p = painted();
  const render::HeightGrid heights = render::surface_heights(p.canvas());
  ASSERT_EQ(heights.width, 90);
  const float top = *std::max_element(heights.mm.begin(), heights.mm.end());
  const float bottom = *std::min_element(heights.mm.begin(), heights.mm.end());
  ASSERT_GT(top - bottom, 0.1f);  // paint stands on the weave
  for (int y = 0; y < 60; y += 7)
    for (int x = 0; x < 90; x += 5)
      ASSERT_EQ(heights.at(x, y), p.canvas().base_height_mm(x, y) + p.canvas().dry_height_mm(x, y) +
                                      p.canvas().wet_volume_mm(x, y));
  // 16-bit PNG: within half a step of the 65535 between the lowest and highest point.
  const auto png = temp_file("h.png");
  render::write_height_map(png, heights);
  const render::HeightGrid from_png = render::read_height_map(png);
  ASSERT_EQ(from_png.width, 90);
  ASSERT_EQ(from_png.height, 60);
  EXPECT_DOUBLE_EQ(from_png.cell_mm, p.canvas().cell_mm());
  const double half_step = 0.5 * (top - bottom) / 65535.0 + 1e-6;
  for (std::size_t i = 0; i < heights.mm.size(); ++i)
    ASSERT_NEAR(from_png.mm[i], heights.mm[i], half_step) << "cell " << i;
  // EXR: the floats themselves.
  const auto exr = temp_file("h.exr");
  render::write_height_map(exr, heights);
  const render::HeightGrid from_exr = render::read_height_map(exr);
  EXPECT_EQ(from_exr.mm, heights.mm);
  EXPECT_DOUBLE_EQ(from_exr.cell_mm, p.canvas().cell_mm());
  EXPECT_THROW(render::write_height_map(temp_file("h.tif"), heights), std::runtime_error);
  std::filesystem::remove(png);
  std::filesystem::remove(exr);
}

TEST(ReliefMaps, TheNormalMapOfASlopeDecodesToItsNormal) {
  // h = a x + b y (mm; y down the rows): the normal is (-a, b, 1) / |.| with +Y up the image.
  render::HeightGrid h;
  h.width = 40;
  h.height = 30;
  h.cell_mm = 0.1;
  const double a = 0.3, b = -0.45;
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x)
      h.mm.push_back(static_cast<float>(a * x * h.cell_mm + b * y * h.cell_mm + 1.0));
  const auto png = temp_file("n.png");
  render::write_normal_map(png, h);
  const render::Image image = render::read_png(png);
  ASSERT_EQ(image.width, 40);
  const double length = std::sqrt(a * a + b * b + 1.0);
  const double expected[3] = {-a / length, b / length, 1.0 / length};
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(2.0 * image.pixel(x, y)[c] - 1.0, expected[c], 1.0 / 255.0 + 1e-3)
            << x << "," << y << " channel " << c;
  // An 8-bit colour PNG is no height map: refused by name.
  try {
    render::read_height_map(png);
    ADD_FAILURE() << "an 8-bit RGB PNG was read as a height map";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a 16-bit greyscale PNG"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(png);
}

double luminance(const render::Image& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

TEST(ReliefMaps, AnExportAtTwiceTheScaleShadesASmoothRelief) {
  const paintcore::Painting p = painted();
  render::RenderSettings settings;
  settings.wavelengths = 4;
  settings.flakes = false;
  const render::Image one = render::render_painting(p, settings);
  const render::Image two = render::render_painting(p.refined(2), settings);
  ASSERT_EQ(two.width, 2 * one.width);
  ASSERT_EQ(two.height, 2 * one.height);
  // Over the stroke: the shading changes between the two pixels inside an old cell about as
  // much as across old cells' edges. A blocky 2x (each cell's pixel copied) would change only
  // across the edges: inside would be 0.
  double inside = 0.0, across = 0.0, mean_one = 0.0, mean_two = 0.0;
  for (int y = 2 * 20; y < 2 * 45; ++y)
    for (int x = 2; x + 2 < two.width - 2; x += 2) {
      inside += std::abs(luminance(two, x + 1, y) - luminance(two, x, y));
      across += std::abs(luminance(two, x + 2, y) - luminance(two, x + 1, y));
    }
  for (int y = 0; y < one.height; ++y)
    for (int x = 0; x < one.width; ++x) mean_one += luminance(one, x, y);
  for (int y = 0; y < two.height; ++y)
    for (int x = 0; x < two.width; ++x) mean_two += luminance(two, x, y);
  ASSERT_GT(across, 0.0);
  EXPECT_GT(inside, 0.6 * across) << "inside " << inside << " across " << across;
  // The same painting: its mean brightness within 2 %.
  mean_one /= one.width * one.height;
  mean_two /= two.width * two.height;
  EXPECT_NEAR(mean_two, mean_one, 0.02 * mean_one);
}

// A varnish is part of the relief: the height map (and every renderer, through
// paintcore::surface_height_mm) is the coat's top where it lies.
TEST(ReliefMaps, TheHeightMapIsTheVarnishsTopWhereItLies) {
  paintcore::Painting p = painted();
  const render::HeightGrid bare = render::surface_heights(p.canvas());
  p.apply_varnish(paintcore::Finish::gloss, 0.05, paintcore::CellRect{30, 10, 60, 40});
  const render::HeightGrid coated = render::surface_heights(p.canvas());
  double added = 0.0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 90; ++x) {
      const bool inside = x >= 30 && x < 60 && y >= 10 && y < 40;
      const double gained = coated.at(x, y) - bare.at(x, y);
      if (!inside) {
        ASSERT_EQ(gained, 0.0) << x << "," << y;
      }
      ASSERT_GE(gained, -1e-6) << x << "," << y;
      added += gained;
    }
  EXPECT_NEAR(added / (30.0 * 30.0), 0.05, 1e-4);  // the coat's volume, levelled or not
}

}  // namespace
