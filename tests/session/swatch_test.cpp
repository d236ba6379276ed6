// The Palette panel's swatch shows the mix as a stroke leaves it on the canvas: it matches
// the rendered stroke itself, its masstone is the mix's opaque colour, and it follows the
// simulated deposit rather than a constant.
#include <gtest/gtest.h>
#include <impasto/data/colorimetry.hpp>
#include <impasto/data/data_dir.hpp>
#include <impasto/data/pigment_library.hpp>
#include <impasto/data/pigments.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render/tile_renderer.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "../common/user_pigment_folder.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/session/swatch.hpp"

namespace impasto::session {
namespace {

SwatchStroke blue_stroke() {
  SwatchStroke stroke;
  stroke.brush.head = "round";
  stroke.brush.size_mm = 6.0;
  stroke.brush.stiffness = 0.5;
  stroke.load.volume_mm3 = 40.0;
  stroke.load.mix = {{"Blue Red Shade", 1.0}};
  stroke.pressure = 0.6f;
  stroke.dpi = 150.0;
  stroke.weave_seed = 0;  // flat: the rendered stroke's shading comes from the paint alone
  return stroke;
}

// Linear sRGB settings, so rendered colours convert to L*a*b* without a curve.
render::RenderSettings linear_settings() {
  render::RenderSettings settings;
  settings.display = render::DisplayEncoding::linear_srgb;
  return settings;
}

data::Lab lab_of(const DisplayRgb& rgb) {
  static const std::array<double, 9> to_xyz = render::invert_3x3(render::xyz_to_linear_srgb());
  const auto xyz_of = [](double r, double g, double b) {
    return data::Xyz{to_xyz[0] * r + to_xyz[1] * g + to_xyz[2] * b,
                     to_xyz[3] * r + to_xyz[4] * g + to_xyz[5] * b,
                     to_xyz[6] * r + to_xyz[7] * g + to_xyz[8] * b};
  };
  return data::xyz_to_lab(xyz_of(rgb[0], rgb[1], rgb[2]), xyz_of(1.0, 1.0, 1.0));
}

double delta_e(const DisplayRgb& a, const DisplayRgb& b) {
  return data::ciede2000(lab_of(a), lab_of(b));
}

// The chip against the same stroke painted in the middle of a window-sized canvas and
// rendered whole, as the window shows it, at nine places a twentieth of a millimetre apart:
// the small swatch painting changes nothing but the weave beneath the stroke and where the
// stroke lies on the cells. At 150 dpi the round's faded bristle relief shades by the latter
// (docs/marks.md, "Texture in millimetres": 0.24-1.26 ΔE2000 over these nine), so the chip
// holds on average (under 1 is not noticeable) and at worst within 1.5.
TEST(Swatch, OnCanvasChipMatchesTheStrokeOnACanvas) {
  SwatchStroke stroke = blue_stroke();
  stroke.weave_seed = 1;  // the window's canvas has a weave
  const render::RenderSettings settings = linear_settings();
  const Swatch swatch = make_swatch(stroke, settings);
  ASSERT_GT(swatch.deposit.painted_cells, 100u);
  ASSERT_GT(swatch.deposit.median_mm, 0.0);

  double sum = 0.0, worst = 0.0;
  for (const double dx : {0.0, 0.05, 0.1}) {
    for (const double dy : {0.0, 0.05, 0.1}) {
      paintcore::Painting canvas(paintcore::CanvasSpec{600, 400, stroke.dpi, stroke.weave_seed}, 1);
      paint_standard_stroke(canvas, stroke, 31.0 + dx, 37.0 + dy);
      // The weave under the stroke differs from place to place, and so do a few edge cells.
      EXPECT_NEAR(static_cast<double>(wet_deposit(canvas).painted_cells),
                  static_cast<double>(swatch.deposit.painted_cells),
                  0.02 * static_cast<double>(swatch.deposit.painted_cells));
      const double on_canvas = delta_e(swatch.on_canvas, mean_stroke_colour(canvas, settings));
      sum += on_canvas;
      worst = std::max(worst, on_canvas);
    }
  }
  const double masstone = delta_e(swatch.masstone, swatch.on_canvas);
  RecordProperty("delta_e_on_canvas_mean", std::to_string(sum / 9));
  RecordProperty("delta_e_on_canvas_worst", std::to_string(worst));
  EXPECT_LT(sum / 9, 1.0) << "the masstone is " << masstone << " away";
  EXPECT_LT(worst, 1.5);
}

// The stroke's area spans each column's painted cells, gaps included, and nothing else; the
// mean colour is the rendered cells' mean over it, checked against a plain loop.
TEST(Swatch, MeanStrokeColourIsTheRenderedMeanOverTheStrokesArea) {
  const paintcore::Painting painting = paint_swatch_stroke(blue_stroke());
  const paintcore::Canvas& canvas = painting.canvas();
  const std::vector<std::uint8_t> area = stroke_area(canvas);
  const int w = canvas.width_cells();
  std::size_t inside = 0, painted_inside = 0;
  for (int y = 0; y < canvas.height_cells(); ++y)
    for (int x = 0; x < w; ++x) {
      const bool painted = canvas.wet_volume_mm(x, y) > kPaintedAboveMm;
      const bool in = area[static_cast<std::size_t>(y * w + x)] != 0;
      if (painted) {
        EXPECT_TRUE(in) << x << "," << y;
      }
      inside += in;
      painted_inside += in && painted;
    }
  ASSERT_EQ(painted_inside, wet_deposit(painting).painted_cells);
  EXPECT_LT(inside, 2 * painted_inside);  // the gaps, not the canvas around the stroke

  const render::RenderSettings settings = linear_settings();
  render::TileRenderer renderer(settings, painting.pigment_slots());
  renderer.render_all(canvas);
  const render::Image image = renderer.image();
  std::array<double, 3> sum{};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (area[static_cast<std::size_t>(y * w + x)])
        for (int c = 0; c < 3; ++c) sum[static_cast<std::size_t>(c)] += image.pixel(x, y)[c];
  const DisplayRgb mean = mean_stroke_colour(painting, settings);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(mean[static_cast<std::size_t>(c)], sum[static_cast<std::size_t>(c)] / inside, 1e-5)
        << "channel " << c;
}

TEST(Swatch, MasstoneIsTheOpaqueLayerAndThinLayersShowTheGround) {
  const render::RenderSettings settings = linear_settings();
  const std::vector<std::vector<input::PigmentPart>> mixes = {{{"Blue Red Shade", 1.0}},
                                                              {{"White", 2.0}, {"Red", 1.0}}};
  const double opaque = masstone_thickness_mm(settings);
  const auto masstones = render_flat_layers(settings, mixes, opaque);
  const auto thicker = render_flat_layers(settings, mixes, 10.0 * opaque);
  const auto bare = render_flat_layers(settings, mixes, 0.0);
  ASSERT_EQ(masstones.size(), 2u);
  for (std::size_t m = 0; m < mixes.size(); ++m) {
    EXPECT_LT(delta_e(masstones[m], thicker[m]), 1e-3) << "mix " << m;
    // Thickening a layer takes it from the ground toward the masstone.
    double last = delta_e(bare[m], masstones[m]);
    for (double t : {0.001, 0.01, 0.1}) {
      const double now =
          delta_e(render_flat_layers(settings, std::span(&mixes[m], 1), t).front(), masstones[m]);
      EXPECT_LT(now, last) << "mix " << m << " at " << t << " mm";
      last = now;
    }
  }
  EXPECT_LT(delta_e(bare[0], bare[1]), 1e-6);  // no paint: both show the ground
  EXPECT_GT(delta_e(masstones[0], masstones[1]), 10.0);
}

TEST(Swatch, ManyPigmentsRenderInBatches) {
  render::RenderSettings settings = linear_settings();
  // A batch's palette is not a single pigment's: a rule trained on the palette differs with
  // it, the Gaussian rule does not.
  settings.node_weights = render::NodeWeights::interpolatory;
  // More pigments than a painting has slots: the bundled ones and copies of Red in the user
  // layer, each a pigment of its own.
  test::UserPigmentFolder folder("impasto_swatch_batches");
  std::filesystem::create_directories(folder.user());
  std::ifstream bundled_red(data::data_dir() / "pigments" / "red.csv");
  const std::string red((std::istreambuf_iterator<char>(bundled_red)), {});
  for (int copy = 1; copy <= 4; ++copy) {
    std::string text = red;
    const std::string name_line = "# name: Red\n";
    text.replace(text.find(name_line), name_line.size(),
                 "# name: Red " + std::to_string(copy) + "\n");
    std::ofstream(folder.user() / ("red_" + std::to_string(copy) + ".csv")) << text;
  }
  data::reload_active_pigment_library();
  const auto& pigments = data::PigmentDatabase::defaults().all();
  std::vector<std::vector<input::PigmentPart>> mixes;
  for (const auto& pigment : pigments) mixes.push_back({{pigment.name, 1.0}});
  ASSERT_GT(mixes.size(), static_cast<std::size_t>(paintcore::kMaxPigmentSlots));
  const auto all = render_flat_layers(settings, mixes, 0.05);
  ASSERT_EQ(all.size(), mixes.size());
  for (std::size_t m = 0; m < mixes.size(); ++m) {
    const auto alone = render_flat_layers(settings, std::span(&mixes[m], 1), 0.05).front();
    EXPECT_EQ(all[m], alone) << pigments[m].name;
  }
}

TEST(Swatch, IsDeterministicAndRejectsBadMixes) {
  const SwatchStroke stroke = blue_stroke();
  const render::RenderSettings settings;
  const Swatch a = make_swatch(stroke, settings);
  const Swatch b = make_swatch(stroke, settings);
  EXPECT_EQ(a.on_canvas, b.on_canvas);
  EXPECT_EQ(a.deposit.median_mm, b.deposit.median_mm);
  SwatchStroke empty = stroke;
  empty.load.mix.clear();
  EXPECT_THROW(make_swatch(empty, settings), std::runtime_error);
  SwatchStroke unknown = stroke;
  unknown.load.mix = {{"Unobtainium", 1.0}};
  EXPECT_THROW(make_swatch(unknown, settings), std::runtime_error);
}

}  // namespace
}  // namespace impasto::session

namespace impasto::session {
namespace {
// A paint chip in the window (the library's masstones rendered together) against the same
// paint laid flat on a painting whose palette is the demo's: rendered under the painting's
// own rule, as the window renders its chips, they agree; under a rule trained on the whole
// library (the chips' own palette, as the window did before) they differ by the two rules.
TEST(Swatch, APaintChipIsItsPaintOnThePainting) {
  const render::RenderSettings settings = linear_settings();
  const std::vector<std::string> slots = demo_palette();
  const render::SpectralSampling painting_rule =
      render::SpectralPalette(settings, slots).sampling();
  std::vector<std::vector<input::PigmentPart>> singles;
  for (const auto& name : slots) singles.push_back({{name, 1.0}});
  const double opaque = masstone_thickness_mm(settings);
  const auto chips = render_flat_layers(settings, singles, opaque, &painting_rule);
  // The whole library's chips under the rule trained on it, this palette's among them.
  std::vector<std::vector<input::PigmentPart>> library;
  for (const auto& name : slots) library.push_back({{name, 1.0}});
  for (const auto& pigment : data::PigmentDatabase::defaults().all())
    if (std::find(slots.begin(), slots.end(), pigment.name) == slots.end())
      library.push_back({{pigment.name, 1.0}});
  const auto own_rule_chips = render_flat_layers(settings, library, opaque);
  // The painting: one cell of each of its paints.
  paintcore::Canvas canvas(paintcore::CanvasSpec{static_cast<int>(slots.size()), 1, 254.0, 0});
  paintcore::Tile& tile = canvas.ensure_tile(0, static_cast<int>(slots.size()));
  for (std::size_t s = 0; s < slots.size(); ++s) {
    tile.wet_volume_mm[s] = static_cast<float>(opaque);
    tile.pigment(static_cast<int>(s))[s] = static_cast<float>(opaque);
  }
  render::TileRenderer renderer(settings, slots);
  renderer.render_all(canvas);
  const render::Image image = renderer.image();
  double worst = 0.0, worst_own_rule = 0.0;
  for (std::size_t s = 0; s < slots.size(); ++s) {
    const float* rgb = image.pixel(static_cast<int>(s), 0);
    const DisplayRgb on_painting{rgb[0], rgb[1], rgb[2]};
    EXPECT_LT(delta_e(chips[s], on_painting), 0.05) << slots[s];
    worst = std::max(worst, delta_e(chips[s], on_painting));
    worst_own_rule = std::max(worst_own_rule, delta_e(own_rule_chips[s], on_painting));
  }
  std::cout << "[ chip ] at most " << worst << " dE00 from the painting under its rule; "
            << worst_own_rule << " under the library's\n";
}
}  // namespace
}  // namespace impasto::session
