// The shading key (shading_key.hpp), the one list of what changes a cell's shading factors,
// which the CPU renderer's relight and the window's cached view compare: each shading setting
// changes it, the colour settings leave it (a new light spectrum reuses the shading), and a
// relight after each shading change gives a fresh render's image, bit for bit.
#include "impasto/render/shading_key.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "white_and_blue_palette.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

struct Change {
  std::string name;
  std::function<void(RenderSettings&)> apply;
};

// Every setting that moves the highlight, the shading or the relief's shadows and occlusion.
std::vector<Change> shading_changes() {
  return {
      {"light_azimuth_deg", [](RenderSettings& s) { s.light_azimuth_deg += 30.0; }},
      {"light_elevation_deg", [](RenderSettings& s) { s.light_elevation_deg -= 20.0; }},
      {"ambient", [](RenderSettings& s) { s.ambient += 0.2; }},
      {"dry_material.specular", [](RenderSettings& s) { s.dry_material.specular += 0.2f; }},
      {"dry_material.shininess", [](RenderSettings& s) { s.dry_material.shininess *= 3.0f; }},
      {"wet_material.specular", [](RenderSettings& s) { s.wet_material.specular += 0.3f; }},
      {"wet_material.shininess", [](RenderSettings& s) { s.wet_material.shininess *= 0.25f; }},
      {"wet_gloss_mm", [](RenderSettings& s) { s.wet_gloss_mm *= 20.0; }},
      {"shadows", [](RenderSettings& s) { s.shadows = !s.shadows; }},
      {"occlusion", [](RenderSettings& s) { s.occlusion = !s.occlusion; }},
      {"shadow_light_diameter_deg", [](RenderSettings& s) { s.shadow_light_diameter_deg *= 4.0; }},
      {"shadow_reach_mm", [](RenderSettings& s) { s.shadow_reach_mm = 0.15; }},
      {"occlusion_radius_mm", [](RenderSettings& s) { s.occlusion_radius_mm *= 3.0; }},
      // The sky's reflection in the paint's surface, and the body seen through it.
      {"saunderson", [](RenderSettings& s) { s.saunderson = !s.saunderson; }},
      {"saunderson_k1", [](RenderSettings& s) { s.saunderson_k1 += 0.01; }},
  };
}

// The colour alone: a relight under them keeps every cell's shading factors.
std::vector<Change> colour_changes() {
  return {
      {"light", [](RenderSettings& s) { s.light = "A"; }},
      {"thickness_scale_mm", [](RenderSettings& s) { s.thickness_scale_mm *= 2.0; }},
      {"display", [](RenderSettings& s) { s.display = DisplayEncoding::linear_srgb; }},
  };
}

TEST(ShadingKey, EachShadingSettingChangesIt) {
  const std::vector<double> key = shading_settings_key(RenderSettings{});
  for (const Change& change : shading_changes()) {
    RenderSettings settings;
    change.apply(settings);
    EXPECT_NE(shading_settings_key(settings), key) << change.name;
  }
}

TEST(ShadingKey, TheColourSettingsLeaveIt) {
  const std::vector<double> key = shading_settings_key(RenderSettings{});
  for (const Change& change : colour_changes()) {
    RenderSettings settings;
    change.apply(settings);
    EXPECT_EQ(shading_settings_key(settings), key) << change.name;
  }
}

std::vector<double> both_keys(const RenderSettings& settings) {
  std::vector<double> key = shading_settings_key(settings);
  const std::vector<double> colour = shader_colour_settings_key(settings);
  key.insert(key.end(), colour.begin(), colour.end());
  return key;
}

// The window's renderer takes a light or material change by copy_shading_settings: each
// shading setting and each shader colour uniform arrives, the palette's settings stay.
TEST(ShadingKey, TheCopyTakesEachShadingAndUniformSettingAndLeavesTheRest) {
  std::vector<Change> changes = shading_changes();
  changes.push_back({"saunderson_k2", [](RenderSettings& s) { s.saunderson_k2 -= 0.1; }});
  changes.push_back({"cracks", [](RenderSettings& s) { s.cracks = !s.cracks; }});
  changes.push_back({"crack_model", [](RenderSettings& s) {
                       s.crack_model = s.crack_model == CrackModel::Corrected
                                           ? CrackModel::Gouffe
                                           : CrackModel::Corrected;
                     }});

  for (const Change& change : changes) {
    RenderSettings changed;
    change.apply(changed);
    RenderSettings copy;
    copy_shading_settings(changed, copy);
    EXPECT_EQ(both_keys(copy), both_keys(changed)) << change.name;
    EXPECT_NE(both_keys(copy), both_keys(RenderSettings{})) << change.name;
  }
  RenderSettings other;
  other.light = "A";
  other.thickness_scale_mm *= 2.0;
  RenderSettings copy;
  copy_shading_settings(other, copy);
  EXPECT_EQ(copy.light, RenderSettings{}.light);
  EXPECT_EQ(copy.thickness_scale_mm, RenderSettings{}.thickness_scale_mm);
}

// One tile of wet ridges over the weave, thick enough to cast shadows, half of it dry.
paintcore::Canvas ridged_canvas() {
  paintcore::Canvas canvas({kTileSize, kTileSize, 254.0, 5});
  paintcore::Tile& tile = canvas.ensure_tile(0, 2);
  for (int c = 0; c < kTileCells; ++c) {
    const auto k = static_cast<std::size_t>(c);
    const float ridge = 0.5f + 0.5f * std::sin(0.3f * static_cast<float>(c % kTileSize));
    const bool dry = c < kTileCells / 2;
    (dry ? tile.dry_height_mm[k] : tile.wet_volume_mm[k]) = 0.05f + 0.6f * ridge;
    tile.pigment(0)[c] = dry ? 0.0f : 0.1f * ridge;
    tile.pigment(1)[c] = dry ? 0.0f : 0.02f;
  }
  return canvas;
}

Image fresh_render(const RenderSettings& settings, const paintcore::Canvas& canvas) {
  TileRenderer renderer(settings, white_and_blue_palette(settings));
  renderer.render_all(canvas);
  return renderer.image();
}

TEST(ShadingKey, ARelightAfterEachChangeEqualsAFreshRender) {
  const paintcore::Canvas canvas = ridged_canvas();
  std::vector<Change> changes = shading_changes();
  for (Change& change : colour_changes()) changes.push_back(std::move(change));
  for (const Change& change : changes) {
    RenderSettings settings;
    settings.light_elevation_deg = 25.0;  // low enough for the ridges to cast shadows
    settings.saunderson = true;           // so that its coefficients show
    TileRenderer renderer(settings, white_and_blue_palette(settings));
    renderer.render_all(canvas);
    const Image before = renderer.image();
    change.apply(settings);
    renderer.set_settings(settings, white_and_blue_palette(settings));
    renderer.render_all(canvas);
    const Image fresh = fresh_render(settings, canvas);
    ASSERT_EQ(renderer.image().rgb.size(), fresh.rgb.size());
    EXPECT_TRUE(renderer.image().rgb == fresh.rgb) << change.name;
    EXPECT_FALSE(before.rgb == fresh.rgb) << change.name << " changes nothing here";
  }
}

}  // namespace
