// Whole paintings to files: PNG and EXR written, PNG read back, bad names rejected.
#include "impasto/render/render_painting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>

using namespace impasto;

namespace {

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impasto_render_test_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

}  // namespace

TEST(RenderPainting, WritesPngOfTheGroundAndExr) {
  paintcore::Painting painting({100, 70, 100.0, 0});
  painting.slot_for("White");
  render::RenderSettings settings;
  settings.dry_material = {0.0f, 10.0f};

  const auto png = temp_file("ground.png");
  render::render_painting_to_file(painting, settings, png);
  const render::Image read = render::read_png(png);
  ASSERT_EQ(read.width, 100);
  ASSERT_EQ(read.height, 70);
  // Titanium white's R∞ under D65, adapted: a near-white, slightly below 1 in every channel.
  for (float v : read.rgb) {
    ASSERT_GT(v, 0.9f);
    ASSERT_LE(v, 1.0f);
  }

  const auto exr = temp_file("ground.exr");
  render::render_painting_to_file(painting, settings, exr);
  EXPECT_GT(std::filesystem::file_size(exr), 0u);
  std::filesystem::remove(png);
  std::filesystem::remove(exr);
}

TEST(RenderPainting, RejectsUnknownExtensionsAndUnwritablePaths) {
  paintcore::Painting painting({64, 64, 100.0, 0});
  const render::RenderSettings settings;
  EXPECT_THROW(render::render_painting_to_file(painting, settings, temp_file("x.jpg")),
               std::runtime_error);
  EXPECT_THROW(render::render_painting_to_file(painting, settings, "/nonexistent/dir/x.png"),
               std::runtime_error);
  EXPECT_THROW(render::render_painting_to_file(painting, settings, "/nonexistent/dir/x.exr"),
               std::runtime_error);
  EXPECT_THROW(render::read_png(temp_file("missing.png")), std::runtime_error);
}

namespace {

// A 64 x 48-cell canvas at 60 dpi (the weave's 0.6 mm threads 1.4 cells apart: finer than
// the cells can show) with a band of thin paint across it.
paintcore::Painting coarse_weave_painting() {
  paintcore::Painting painting({64, 48, 60.0, 7});
  painting.set_brush(paintcore::BrushSettings{"flat", 8.0, 0.6});
  painting.load_brush({{"Blue Red Shade", 1.0}}, 20.0);
  painting.begin_stroke();
  for (int i = 0; i <= 40; ++i) {
    paintcore::PenSample sample;
    sample.time_s = 0.01 * i;
    sample.x_mm = 3.0 + 0.5 * i;
    sample.y_mm = 10.0;
    sample.pressure = 0.6f;
    painting.stroke_to(sample);
  }
  painting.end_stroke();
  return painting;
}

double mean_difference(const render::Image& a, const render::Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(a.rgb[i] - b.rgb[i]);
  return sum / static_cast<double>(a.rgb.size());
}

}  // namespace

// Supersampling converges: 2 x 2 samples a pixel are closer to 4 x 4 than one sample is, and
// one sample is the plain render exactly. A flat, uniform canvas (no weave) is the same at any
// supersampling (the encode round trip through linear light and XYZ loses nothing).
TEST(RenderPainting, SupersamplingConvergesAndLeavesAUniformCanvasAlone) {
  const paintcore::Painting painting = coarse_weave_painting();
  const render::RenderSettings settings;
  const render::Image plain = render::render_painting(painting, settings);
  const render::Image one = render::render_painting_supersampled(painting, settings, 1);
  EXPECT_EQ(one.rgb, plain.rgb);
  const render::Image two = render::render_painting_supersampled(painting, settings, 2);
  const render::Image four = render::render_painting_supersampled(painting, settings, 4);
  ASSERT_EQ(two.width, 64);
  ASSERT_EQ(four.height, 48);
  const double error_one = mean_difference(one, four), error_two = mean_difference(two, four);
  std::cout << "[ supersample ] mean |1 - 4| " << error_one << ", |2 - 4| " << error_two << "\n";
  EXPECT_GT(error_one, 0.0);
  EXPECT_LT(error_two, 0.6 * error_one);

  paintcore::Painting flat({32, 24, 150.0, 0});
  flat.slot_for("White");
  const render::Image flat_one = render::render_painting(flat, settings);
  const render::Image flat_four = render::render_painting_supersampled(flat, settings, 4);
  for (std::size_t i = 0; i < flat_one.rgb.size(); ++i)
    ASSERT_NEAR(flat_four.rgb[i], flat_one.rgb[i], 2e-4) << i;
  EXPECT_THROW(render::render_painting_supersampled(painting, settings, 5), std::runtime_error);
}
