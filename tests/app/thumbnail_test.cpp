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

}  // namespace
}  // namespace impasto::app
