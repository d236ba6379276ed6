// The bundled metallic study replayed and rendered: sparkles where the top paint holds flake
// pigment and nowhere else, and none under an overcast sky.
#include <gtest/gtest.h>

#include <impasto/input/stroke_import.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>

#include "impasto/session/replay.hpp"

namespace impasto::session {
namespace {

const std::filesystem::path kMetallic =
    std::filesystem::path(IMPASTO_SOURCE_DIR) / "data/strokes/metallic.strokes";

int slot_of(const paintcore::Painting& painting, const std::string& name) {
  const auto& slots = painting.pigment_slots();
  const auto it = std::find(slots.begin(), slots.end(), name);
  return it == slots.end() ? -1 : static_cast<int>(it - slots.begin());
}

std::size_t differing_pixels(const render::Image& a, const render::Image& b, int x, int y) {
  const float* p = a.pixel(x, y);
  const float* q = b.pixel(x, y);
  return p[0] != q[0] || p[1] != q[1] || p[2] != q[2] ? 1 : 0;
}

TEST(FlakeReplay, MetallicStudySparklesOnlyWhereFlakePaintIs) {
  // At half the file's resolution (0.2 mm cells, the same 40 × 30 mm) to keep the test quick.
  ReplayOptions options;
  options.width_cells = 200;
  options.height_cells = 150;
  options.dpi = 127.0;
  const paintcore::Painting painting = replay(input::load_strokes_any(kMetallic), options, nullptr);
  const int aluminium = slot_of(painting, "Aluminium Metallic");
  const int pearl = slot_of(painting, "Mica Blue Pearl");
  const int blue = slot_of(painting, "Blue Red Shade");
  ASSERT_GE(aluminium, 0);
  ASSERT_GE(pearl, 0);
  ASSERT_GE(blue, 0);

  const paintcore::Canvas& canvas = painting.canvas();
  auto flake_paint_at = [&](int x, int y) {
    return canvas.pigment_mm(x, y, aluminium) > 0.0f || canvas.pigment_mm(x, y, pearl) > 0.0f;
  };
  std::size_t flake_cells = 0, other_painted_cells = 0;
  for (int y = 0; y < canvas.height_cells(); ++y) {
    for (int x = 0; x < canvas.width_cells(); ++x) {
      if (flake_paint_at(x, y)) {
        ++flake_cells;
      } else if (canvas.pigment_mm(x, y, blue) > 0.0f) {
        ++other_painted_cells;
      }
    }
  }
  EXPECT_GT(flake_cells, 5000u);
  EXPECT_GT(other_painted_cells, 2000u);

  // The sun (0.53°) lights few flakes of 0.2 mm cells; a 4° lamp many more (⟨N⟩ ∝ Δ²);
  // diffuse light none. The light's kind and size change only the sparkles, so one image
  // without flakes serves all three.
  struct Light {
    const char* name;
    render::LightType type;
    double size_deg;
    std::size_t at_least, at_most;
  };
  render::RenderSettings calm;
  calm.display = render::DisplayEncoding::linear_srgb;
  calm.wavelengths = 4;
  calm.flakes = false;
  const render::Image plain = render::render_painting(painting, calm);
  for (const Light& light : {Light{"sun", render::LightType::directional, 0.53, 3, 600},
                             // (Thick paint tilts more flakes to the light: ~1.5 % of flake cells
                             // glint in the sun, ~45 % under the lamp.)
                             Light{"lamp", render::LightType::directional, 4.0, 1000, 12000},
                             Light{"overcast", render::LightType::diffuse, 0.53, 0, 0}}) {
    render::RenderSettings settings = calm;
    settings.flakes = true;
    settings.light_type = light.type;
    settings.light_size_deg = light.size_deg;
    const render::Image sparkling = render::render_painting(painting, settings);
    std::size_t sparkles = 0, stray = 0;
    for (int y = 0; y < canvas.height_cells(); ++y) {
      for (int x = 0; x < canvas.width_cells(); ++x) {
        (flake_paint_at(x, y) ? sparkles : stray) += differing_pixels(sparkling, plain, x, y);
      }
    }
    std::cout << "[ " << light.name << " ] " << sparkles << " sparkling cells of " << flake_cells
              << " with flake paint\n";
    EXPECT_EQ(stray, 0u) << light.name << ": sparkles where no flake paint is";
    EXPECT_GE(sparkles, light.at_least) << light.name;
    EXPECT_LE(sparkles, light.at_most) << light.name;
  }
}

}  // namespace
}  // namespace impasto::session
