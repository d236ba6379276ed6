// Whole paintings to files: PNG and EXR written, PNG read back, bad names rejected.
#include "impasto/render/render_painting.hpp"

#include "impasto/render/png_encoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>

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

namespace {

// A 300 x 260-cell painting at 150 dpi with thick strokes across and down it, and dry paint
// under them: shadows and occlusion cross every band boundary.
paintcore::Painting banded_painting() {
  paintcore::Painting painting({300, 260, 150.0, 3});
  painting.set_brush(paintcore::BrushSettings{"round", 6.0, 0.5});
  const auto stroke = [&](double x0, double y0, double x1, double y1) {
    painting.load_brush({{"Blue Red Shade", 1.0}, {"White", 2.0}}, 80.0);
    painting.begin_stroke();
    for (int i = 0; i <= 30; ++i) {
      paintcore::PenSample sample;
      sample.time_s = 0.01 * i;
      sample.x_mm = x0 + (x1 - x0) * i / 30.0;
      sample.y_mm = y0 + (y1 - y0) * i / 30.0;
      sample.pressure = 0.8f;
      sample.buttons = paintcore::kPenTip | paintcore::kPenInRange;
      painting.stroke_to(sample);
    }
    painting.end_stroke();
  };
  stroke(5.0, 20.0, 45.0, 22.0);
  painting.dry(1.0);
  stroke(25.0, 3.0, 27.0, 40.0);
  return painting;
}

}  // namespace

// A painting rendered a band of rows at a time is the painting rendered whole, bit for bit:
// each band reads the margins its shadows and occlusion reach (a low light: long shadows).
TEST(RenderPainting, ByBandsIsTheWholeRenderBitForBit) {
  const paintcore::Painting painting = banded_painting();
  for (const auto light : {render::LightType::directional, render::LightType::diffuse}) {
    render::RenderSettings settings;
    settings.light_type = light;
    settings.light_azimuth_deg = 280.0;  // from above, a little left: shadows down the rows
    settings.light_elevation_deg = 15.0;
    ASSERT_TRUE(render::renders_by_bands(painting, settings));
    const render::Image whole = render::render_painting(painting, settings);
    render::Image banded{whole.width, whole.height, std::vector<float>(whole.rgb.size(), -1.0f)};
    int bands = 0, next_row = 0;
    std::uint64_t last_done = 0, last_total = 0;
    render::render_painting_by_bands(
        painting, settings, 64,
        [&](int first_row, const render::Image& band) {
          EXPECT_EQ(first_row, next_row);
          EXPECT_EQ(band.width, whole.width);
          next_row += band.height;
          ++bands;
          std::copy(band.rgb.begin(), band.rgb.end(),
                    banded.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(first_row) * band.width);
        },
        [&](std::uint64_t done, std::uint64_t total) {
          EXPECT_GE(done, last_done) << "progress runs over all the bands, never back";
          last_done = done;
          last_total = total;
        });
    EXPECT_EQ(bands, 5);
    EXPECT_EQ(next_row, whole.height);
    EXPECT_EQ(last_done, last_total);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < whole.rgb.size(); ++i) differing += whole.rgb[i] != banded.rgb[i];
    EXPECT_EQ(differing, 0u) << "light " << static_cast<int>(light);
    // And the PNG of its bytes is the PNG of the whole image.
    std::vector<std::uint8_t> bytes(banded.rgb.size());
    render::to_png_bytes(banded.rgb.data(), banded.rgb.size(), bytes.data());
    EXPECT_TRUE(render::encode_png_bytes(bytes, banded.width, banded.height) ==
                render::encode_png(whole))
        << "the PNG's bytes differ";
  }
}

// What bands cannot render as the whole does is rendered whole: a point or spot light is placed
// from the canvas's centre.
TEST(RenderPainting, APointLightIsNotRenderedByBands) {
  const paintcore::Painting painting = banded_painting();
  render::RenderSettings settings;
  EXPECT_THROW(render::render_painting_by_bands(painting, settings, 0, [](int, const auto&) {}),
               std::runtime_error)
      << "bands of no rows";
  settings.light_type = render::LightType::point;
  EXPECT_FALSE(render::renders_by_bands(painting, settings));
  settings.light_type = render::LightType::spot;
  EXPECT_FALSE(render::renders_by_bands(painting, settings));
}

// Refined for a larger export (Painting::refined), a band at a time from the coarse rows each
// band reads, the render is the whole refined painting's, bit for bit.
TEST(RenderPainting, RefinedByBandsIsTheWholeRefinedRenderBitForBit) {
  const paintcore::Painting painting = banded_painting();
  render::RenderSettings shaded;
  shaded.light_azimuth_deg = 100.0;  // from below: shadows up the rows
  shaded.light_elevation_deg = 20.0;
  // Without shadows or occlusion a cell reads only its neighbours: the coarse rows the finer
  // ones are interpolated from are then all the margin a band has.
  render::RenderSettings flat_lit = shaded;
  flat_lit.shadows = false;
  flat_lit.occlusion = false;
  for (const auto& [scale, settings] :
       {std::pair{2, shaded}, std::pair{3, shaded}, std::pair{3, flat_lit}}) {
    const render::Image whole = render::render_painting(painting.refined(scale), settings);
    render::Image banded{whole.width, whole.height, std::vector<float>(whole.rgb.size(), -1.0f)};
    int next_row = 0;
    render::render_painting_by_bands(
        painting, settings, 128,
        [&](int first_row, const render::Image& band) {
          ASSERT_EQ(first_row, next_row);
          ASSERT_EQ(band.width, whole.width);
          next_row += band.height;
          std::copy(band.rgb.begin(), band.rgb.end(),
                    banded.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(first_row) * band.width);
        },
        {}, scale);
    EXPECT_EQ(next_row, whole.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < whole.rgb.size(); ++i) differing += whole.rgb[i] != banded.rgb[i];
    EXPECT_EQ(differing, 0u) << "scale " << scale;
  }
}

// A PNG written a band of rows at a time is encode_png's file, whatever the bands, and reads
// back as its pixels; rows out of strip order are refused.
TEST(RenderPainting, APngWrittenByBandsIsTheWholeFile) {
  const int width = 37, height = 200;  // three whole strips and a part
  render::Image image{width, height, std::vector<float>(3 * width * height)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = static_cast<float>((i * 2654435761u) % 997) / 996.0f;
  const std::string whole = render::encode_png(image);
  std::vector<std::uint8_t> bytes(image.rgb.size());
  render::to_png_bytes(image.rgb.data(), image.rgb.size(), bytes.data());
  for (const int band : {64, 128, 192}) {
    std::string png;
    render::PngRowWriter writer(width, height, [&](std::string_view part) { png += part; });
    for (int y = 0; y < height; y += band) {
      EXPECT_FALSE(writer.finished());
      writer.add_rows(bytes.data() + 3 * static_cast<std::size_t>(y) * width,
                      std::min(band, height - y));
    }
    EXPECT_TRUE(writer.finished());
    EXPECT_TRUE(png == whole) << "bands of " << band << " rows: the bytes differ";
  }
  const auto file = temp_file("bands.png");
  std::ofstream(file, std::ios::binary) << whole;
  const render::Image back = render::read_png(file);
  ASSERT_EQ(back.rgb.size(), bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i)
    ASSERT_EQ(std::lround(back.rgb[i] * 255.0f), bytes[i]) << i;
  std::filesystem::remove(file);
  std::string ignored;
  render::PngRowWriter writer(width, height, [&](std::string_view part) { ignored += part; });
  writer.add_rows(bytes.data(), 10);  // not a whole strip, and not the end
  EXPECT_THROW(writer.add_rows(bytes.data(), 10), std::runtime_error);
  EXPECT_THROW(writer.add_rows(bytes.data(), height), std::runtime_error);
}
