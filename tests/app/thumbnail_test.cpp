// `impasto thumbnail`: a painting to a small PNG for file managers; the box filter behind it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"
#include "thumbnail.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

render::Image gradient(int width, int height) {
  render::Image image{width, height, {}};
  image.rgb.resize(3 * static_cast<std::size_t>(width * height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = static_cast<float>(x + 10 * y + c);
  return image;
}

TEST(Thumbnail, ShrinksTheLongerSideAndAveragesWhatEachPixelCovers) {
  const render::Image small = shrink_to_fit(gradient(8, 4), 4);
  ASSERT_EQ(small.width, 4);
  ASSERT_EQ(small.height, 2);
  // Output (1, 1) covers input columns 2..3 and rows 2..3: mean x 2.5, mean y 2.5.
  EXPECT_FLOAT_EQ(small.pixel(1, 1)[0], 2.5f + 25.0f);
  EXPECT_FLOAT_EQ(small.pixel(1, 1)[2], 2.5f + 25.0f + 2.0f);
}

TEST(Thumbnail, NeverEnlargesAndRefusesAZeroSize) {
  const render::Image image = gradient(5, 3);
  const render::Image same = shrink_to_fit(image, 64);
  EXPECT_EQ(same.width, 5);
  EXPECT_EQ(same.rgb, image.rgb);
  EXPECT_THROW(shrink_to_fit(image, 0), std::runtime_error);
}

TEST(Thumbnail, APaintingBecomesAPngWithinTheSize) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_thumbnail_" + std::to_string(getpid()));
  fs::create_directories(dir);
  paintcore::Painting({96, 48, 254.0, 1}, 1).save(dir / "wide.impasto");
  write_thumbnail(dir / "wide.impasto", dir / "wide.png", 32);
  const render::Image png = render::read_png(dir / "wide.png");
  EXPECT_EQ(png.width, 32);
  EXPECT_EQ(png.height, 16);
  EXPECT_THROW(write_thumbnail(dir / "missing.impasto", dir / "x.png", 32), std::runtime_error);
  fs::remove_all(dir);
}

TEST(Thumbnail, RendersAboutTwoCellsAPixelNeverUnderOneDpi) {
  EXPECT_EQ(thumbnail_coarsening({16384, 8192, 300.0, 1}, 256), 32);
  EXPECT_EQ(thumbnail_coarsening({96, 48, 254.0, 1}, 32), 1);  // small: rendered as it is
  EXPECT_EQ(thumbnail_coarsening({16384, 16384, 10.0, 1}, 64), 10);
}

TEST(Thumbnail, ABigPaintingIsRenderedCoarseAndShowsItsPaint) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_thumbnail_big_" + std::to_string(getpid()));
  fs::create_directories(dir);
  // 1200 x 400 cells (0.254 mm) with a band of red along the middle: 9 times coarser for 64
  // pixels, the band about two pixels high.
  paintcore::Painting painting({1200, 400, 100.0, 1}, 1);
  painting.set_brush(paintcore::BrushSettings{.head = "round", .size_mm = 10.0, .stiffness = 0.5});
  painting.load_brush({{"Red", 1.0}}, 3000.0);
  painting.begin_stroke();
  for (int i = 0; i <= 40; ++i)
    painting.stroke_to({.time_s = 0.05 * i,
                        .x_mm = 20.0 + 6.0 * i,
                        .y_mm = 50.8,
                        .pressure = 1.0f,
                        .buttons = paintcore::kPenTip});
  painting.end_stroke();
  painting.save(dir / "big.impasto");
  write_thumbnail(dir / "big.impasto", dir / "big.png", 64);
  const render::Image png = render::read_png(dir / "big.png");
  ASSERT_EQ(png.width, 64);
  ASSERT_EQ(png.height, 21);
  const float* canvas = png.pixel(32, 3);
  const float* paint = png.pixel(32, 10);
  EXPECT_GT(paint[0] - paint[2], canvas[0] - canvas[2] + 0.2f) << "the band is red";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace impasto::app
