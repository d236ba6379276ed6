// One colour path: a pigment's swatches (the Pigment editor, `impasto pigments swatch`, the
// pigment figures, the colour target's recipe) are what the renderer draws for the same flat
// layer under a uniform sky, at the reference (every nm) and at any node count.
#include "impasto/render/pigment_swatches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "flat_layer_canvas.hpp"
#include "impasto/data/colorimetry.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/chromatic_adaptation.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {
namespace {

using paintcore::kTileSize;

// The renderer's pixel (linear sRGB, adapted to D65) as L*a*b* relative to D65.
data::Lab rendered_lab(TileRenderer& renderer, const paintcore::Canvas& canvas) {
  renderer.render_all(canvas);
  const Image image = renderer.image();
  const float* rgb = image.pixel(kTileSize / 2, kTileSize / 2);
  const auto to_xyz = invert_3x3(xyz_to_linear_srgb());
  data::Xyz xyz;
  double* out[3] = {&xyz.X, &xyz.Y, &xyz.Z};
  for (std::size_t i = 0; i < 3; ++i)
    *out[i] =
        100.0 * (to_xyz[3 * i] * rgb[0] + to_xyz[3 * i + 1] * rgb[1] + to_xyz[3 * i + 2] * rgb[2]);
  return data::xyz_to_lab(xyz, {100.0 * kD65WhiteXyz[0], 100.0, 100.0 * kD65WhiteXyz[2]});
}

// A swatch (L*a*b* relative to the light's white) adapted to D65 as the renderer adapts.
data::Lab swatch_lab_d65(const SwatchColour& swatch, const SpectralSampling& sampling) {
  const Matrix3 adapt = bradford_matrix(sampling.white_xyz, kD65WhiteXyz);
  const Xyz d65 = apply(adapt, {swatch.xyz.X / 100, swatch.xyz.Y / 100, swatch.xyz.Z / 100});
  return data::xyz_to_lab({100 * d65[0], 100 * d65[1], 100 * d65[2]},
                          {100.0 * kD65WhiteXyz[0], 100.0, 100.0 * kD65WhiteXyz[2]});
}

struct Gap {
  double max = 0.0;
  std::string worst;
  void add(double de, const std::string& what) {
    if (de > max) max = de, worst = what;
  }
};

// Masstones, tints 1:1 and 1:9 and a glaze over the canvas ground of every bundled pigment:
// the swatch at the palette's own wavelengths against the renderer's flat layer.
Gap swatches_against_renderer(RenderSettings settings) {
  settings.ambient = 1.0;  // the instrument's sky: the surface's reflection k1 with the body
  settings.display = DisplayEncoding::linear_srgb;
  const data::PigmentDatabase& db = data::PigmentDatabase::defaults();
  const data::Pigment& white = db.get("White");
  std::vector<std::string> names;
  for (const data::Pigment& p : db.all())
    if (p.name != "White") names.push_back(p.name);
  names.push_back("White");
  const std::size_t white_slot = names.size() - 1;
  TileRenderer renderer(settings, names);
  const SpectralPalette& palette = renderer.palette();
  const SpectralSampling& sampling = palette.sampling();
  const std::vector<float> ground(palette.ground(), palette.ground() + palette.nodes());
  Gap gap;
  for (std::size_t i = 0; i < white_slot; ++i) {
    const data::Pigment& pigment = db.get(names[i]);
    for (const int parts : {0, 1, 9}) {
      std::vector<double> c(names.size(), 0.0);
      c[i] = 1.0;
      c[white_slot] = parts;
      const SwatchColour swatch = describe_colour(
          "tint", seen_through_surface(tint_reflectance(pigment, white, parts, sampling)),
          sampling);
      gap.add(data::ciede2000(swatch_lab_d65(swatch, sampling),
                              rendered_lab(renderer, test::flat_layer_canvas(c, 2.0f))),
              names[i] + " 1:" + std::to_string(parts));
    }
    std::vector<double> c(names.size(), 0.0);
    c[i] = 1.0;
    const auto glaze_mm = static_cast<float>(kGlazeThickness * settings.thickness_scale_mm);
    const SwatchColour swatch = describe_colour(
        "glaze",
        seen_through_surface(glaze_reflectance(pigment, kGlazeThickness, ground, sampling)),
        sampling);
    gap.add(data::ciede2000(swatch_lab_d65(swatch, sampling),
                            rendered_lab(renderer, test::flat_layer_canvas(c, glaze_mm))),
            names[i] + " glaze");
  }
  return gap;
}

TEST(PigmentSwatches, AreWhatTheRendererDrawsAtTheReference) {
  for (const char* light : {"D65", "A", "F11"}) {
    RenderSettings settings;
    settings.light = light;
    settings.wavelengths = 0;
    const Gap gap = swatches_against_renderer(settings);
    std::cout << "[ swatch ] " << light << " every nm: at most " << gap.max << " dE00 ("
              << gap.worst << ")\n";
    EXPECT_LT(gap.max, 0.05) << light << ": " << gap.worst;
  }
}

TEST(PigmentSwatches, AreWhatTheRendererDrawsAtAnyNodeCount) {
  for (const int nodes : {3, 4, 8, 16}) {
    for (const NodeWeights weights : {NodeWeights::interpolatory, NodeWeights::optimised}) {
      RenderSettings settings;
      settings.wavelengths = nodes;
      settings.node_weights = weights;
      const Gap gap = swatches_against_renderer(settings);
      std::cout << "[ swatch ] " << nodes << " nodes, " << util::name_of(kNodeWeightsNames, weights)
                << ": at most " << gap.max << " dE00 (" << gap.worst << ")\n";
      EXPECT_LT(gap.max, 0.05) << nodes << " nodes: " << gap.worst;
    }
  }
}

// The reference swatch is the full spectrum's: a perfect white seen through nothing is L* 100,
// and the default sampling is every nm of the renderer's range.
TEST(PigmentSwatches, TheDefaultSamplingIsTheRenderersReference) {
  const data::Spectrum d65 = data::light_from_spec("D65");
  const SpectralSampling sampling = swatch_sampling(d65);
  EXPECT_TRUE(sampling.full_spectrum);
  const std::vector<float> one(static_cast<std::size_t>(sampling.size()), 1.0f);
  const SwatchColour white = describe_colour("white", one, sampling);
  EXPECT_NEAR(white.lab.L, 100.0, 1e-4);
  EXPECT_NEAR(white.lab.a, 0.0, 1e-4);
  EXPECT_NEAR(white.lab.b, 0.0, 1e-4);
}

}  // namespace
}  // namespace impasto::render
