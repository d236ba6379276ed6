// The tile renderer's spectral kernels (structure-of-arrays over the nodes, SIMD) against the
// scalar reference (kubelka_munk_cell.hpp, paint_layer.hpp): e^x, a layer over many cells, whole
// renders with dry and wet paint, relief, half storage and Saunderson; the shading factors a
// relight reuses against a fresh render; and the parallel PNG encoder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/png_encoder.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "spectral_kernels.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

std::vector<data::Pigment> test_pigments() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Black"), db.get("Blue Green Shade"), db.get("Cold Yellow"),
          db.get("Magenta")};
}

SpectralPalette make_palette(const RenderSettings& settings, const char* light = "D65") {
  const auto pigments = test_pigments();
  return SpectralPalette(settings, data::light_from_spec(light), pigments,
                         hiding_reflectance(pigments[0]));
}

// 3×2 tiles with the weave, ridges of wet paint of every pigment mixed cell by cell (some
// cells bare, some with a trace of pigment, a few very thick), and a dry layer under tile 4.
paintcore::Canvas varied_canvas() {
  paintcore::Canvas canvas({3 * kTileSize, 2 * kTileSize - 7, 254.0, 3});
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int t : {0, 1, 4, 5}) {
    paintcore::Tile& tile = canvas.ensure_tile(t, 5);
    for (int c = 0; c < kTileCells; ++c) {
      const auto k = static_cast<std::size_t>(c);
      const float ridge = 0.5f + 0.5f * std::sin(0.4f * static_cast<float>(c % kTileSize));
      const float v = unit(random) < 0.1f ? 0.0f : 0.002f + 0.8f * ridge * ridge;
      tile.wet_volume_mm[k] = unit(random) < 0.01f ? 4.0f : v;
      for (int s = 0; s < 5; ++s) {
        const float share = unit(random);
        tile.pigment(s)[c] = share < 0.4f ? 0.0f : share < 0.45f ? 1e-7f : 0.3f * share * v;
      }
    }
  }
  paintcore::DryTile dry;
  dry.tile_index = 4;
  dry.volume_mm.assign(kTileCells, 0.05f);
  dry.slots = {1, 3};
  dry.pigment_mm.assign(2 * kTileCells, 0.01f);
  canvas.dry_layers().push_back({{dry}});
  canvas.ensure_tile(4, 5).dry_height_mm.fill(0.05f);
  return canvas;
}

Image render_canvas(const RenderSettings& settings, const paintcore::Canvas& canvas, bool reference,
                    const char* light = "D65") {
  TileRenderer renderer(settings, make_palette(settings, light));
  renderer.use_reference_kernels(reference);
  renderer.render_all(canvas);
  return renderer.image();
}

// The largest difference of two images' values.
float largest_difference(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgb.size(), b.rgb.size());
  float largest = 0.0f;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) {
    largest = std::max(largest, std::abs(a.rgb[i] - b.rgb[i]));
  }
  return largest;
}

}  // namespace

TEST(SpectralKernels, FastExpIsWithinAFewUlpsOfTheLibrary) {
  double worst = 0.0;
  for (float x = -87.0f; x <= 88.0f; x += 0.001373f) {
    const double exact = std::exp(static_cast<double>(x));
    worst = std::max(worst, std::abs(kernels::fast_exp(x) - exact) / exact);
  }
  EXPECT_LT(worst, 2.5e-7);
  EXPECT_EQ(kernels::fast_exp(0.0f), 1.0f);
  EXPECT_GT(kernels::fast_exp(-1e4f), 0.0f);  // clamped: tiny, never NaN or negative
  EXPECT_LT(kernels::fast_exp(-1e4f), 1e-37f);
}

TEST(SpectralKernels, ALayerOverManyCellsMatchesTheReference) {
  RenderSettings settings;
  for (int nodes : {3, 8, 12, 16}) {
    settings.wavelengths = nodes;
    const SpectralPalette palette = make_palette(settings);
    const kernels::PaddedPalette padded(palette, settings);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    constexpr int kCells = 500;
    std::vector<float> volume(kCells);
    std::vector<std::vector<float>> amounts(5, std::vector<float>(kCells));
    for (int c = 0; c < kCells; ++c) {
      // From nothing through films of a few nm to 50 mm: every branch of the maths.
      volume[static_cast<std::size_t>(c)] =
          c % 7 == 0 ? 0.0f : std::pow(10.0f, -8.0f + 9.7f * unit(random));
      for (auto& slot : amounts) {
        slot[static_cast<std::size_t>(c)] =
            unit(random) < 0.5f ? 0.0f : unit(random) * volume[static_cast<std::size_t>(c)];
      }
    }
    const int pigments[5] = {0, 1, 2, 3, 4};
    const float* pointers[5] = {amounts[0].data(), amounts[1].data(), amounts[2].data(),
                                amounts[3].data(), amounts[4].data()};
    std::vector<float> fast(static_cast<std::size_t>(kCells * padded.padded), 0.0f);
    for (int c = 0; c < kCells; ++c) {
      std::copy_n(palette.ground(), nodes, &fast[static_cast<std::size_t>(c * padded.padded)]);
    }
    const float optical_per_mm = 200.0f;
    kernels::composite_layer_cells(padded, {volume.data(), 5, pigments, pointers}, kCells,
                                   optical_per_mm, fast.data());
    double worst = 0.0;
    for (int c = 0; c < kCells; ++c) {
      std::vector<float> reference(palette.ground(), palette.ground() + nodes);
      std::vector<PigmentShare> shares;
      const float v = volume[static_cast<std::size_t>(c)];
      if (v > 0.0f) {
        for (int s = 0; s < 5; ++s) {
          const float amount = amounts[static_cast<std::size_t>(s)][static_cast<std::size_t>(c)];
          if (amount > 0.0f) shares.push_back({s, pigment_concentration(amount, 1.0f / v)});
        }
        composite_paint_layer(palette, shares, v * optical_per_mm, reference.data());
      }
      for (int i = 0; i < nodes; ++i) {
        const float got = fast[static_cast<std::size_t>(c * padded.padded + i)];
        ASSERT_TRUE(std::isfinite(got));
        worst = std::max(worst, static_cast<double>(std::abs(got - reference[i])));
      }
      for (int i = nodes; i < padded.padded; ++i) {  // the padding stays zero
        EXPECT_EQ(fast[static_cast<std::size_t>(c * padded.padded + i)], 0.0f);
      }
    }
    // Reflectances in [0, 1]: a few float ulps apart (e^x and one division differ).
    EXPECT_LT(worst, 2e-6) << "N=" << nodes;
  }
}

TEST(SpectralKernels, RendersMatchTheScalarReference) {
  const paintcore::Canvas canvas = varied_canvas();
  RenderSettings settings;
  for (int nodes : {4, 8, 16}) {
    for (bool half : {false, true}) {
      for (bool saunderson : {false, true}) {
        settings.wavelengths = nodes;
        settings.storage = half ? ReflectanceStorage::float16 : ReflectanceStorage::float32;
        settings.saunderson = saunderson;
        const Image fast = render_canvas(settings, canvas, false);
        const Image reference = render_canvas(settings, canvas, true);
        // Display-encoded values in [0, 1]: far below a 16-bit step.
        EXPECT_LT(largest_difference(fast, reference), 2e-5f)
            << "N=" << nodes << " half=" << half << " saunderson=" << saunderson;
      }
    }
  }
}

TEST(SpectralKernels, ARelightEqualsAFreshRenderUnderTheNewLight) {
  paintcore::Canvas canvas = varied_canvas();
  RenderSettings settings;
  TileRenderer renderer(settings, make_palette(settings, "D65"));
  renderer.render_all(canvas);
  // A new light spectrum: the cached shading factors are reused, bit for bit a fresh render.
  settings.light = std::string(1, 'A');
  renderer.set_settings(settings, make_palette(settings, "A"));
  renderer.render_all(canvas);
  const Image fresh_a = render_canvas(settings, canvas, false, "A");
  EXPECT_EQ(largest_difference(renderer.image(), fresh_a), 0.0f);

  // Wet paint turned dry at the same heights changes the gloss: not reused.
  paintcore::Tile& tile = canvas.ensure_tile(1, 5);
  for (int c = 0; c < kTileCells; ++c) {
    const auto k = static_cast<std::size_t>(c);
    tile.dry_height_mm[k] += tile.wet_volume_mm[k];
    tile.wet_volume_mm[k] = 0.0f;
  }
  renderer.render_all(canvas);
  EXPECT_EQ(largest_difference(renderer.image(), render_canvas(settings, canvas, false, "A")),
            0.0f);

  // A new light direction: the shading is recomputed.
  settings.light_azimuth_deg = 40.0;
  renderer.set_settings(settings, make_palette(settings, "A"));
  renderer.render_all(canvas);
  EXPECT_EQ(largest_difference(renderer.image(), render_canvas(settings, canvas, false, "A")),
            0.0f);
}

TEST(PngEncoder, DecodesToTheRoundedValuesWhateverTheThreads) {
  Image image;
  image.width = 301;
  image.height = 157;  // several strips, the last one short
  image.rgb.resize(3 * 301 * 157);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(-0.2f, 1.2f);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    // Smooth areas (the filters matter) and noise, values out of range and NaN.
    image.rgb[i] = i % 97 == 0           ? NAN
                   : (i / 3) % 301 < 150 ? 0.3f + 0.001f * (i % 300)
                                         : unit(random);
  }
  const std::string one = encode_png(image, 1);
  EXPECT_EQ(encode_png(image, 2), one);
  EXPECT_EQ(encode_png(image, 0), one);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "impasto_png_encoder_test.png";
  write_png(file, image);
  const Image back = read_png(file);
  std::filesystem::remove(file);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const float v = std::isnan(image.rgb[i]) ? 0.0f : std::clamp(image.rgb[i], 0.0f, 1.0f);
    ASSERT_EQ(std::lround(back.rgb[i] * 255.0f), std::lround(v * 255.0f)) << "value " << i;
  }
}
