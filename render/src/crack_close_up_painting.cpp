// The close-up of a whole painting: its cells' colours from the ordinary renderer, then the
// cracks magnified over them (crack_close_up.cpp).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impasto/render/crack_close_up.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

Image render_painting_close_up(const paintcore::Painting& painting, const RenderSettings& settings,
                               const CellRegion& region, int pixels_per_cell) {
  RenderSettings flat = settings;
  flat.cracks = false;  // the cells as if uncracked: the close-up draws the cracks
  flat.display = DisplayEncoding::linear_srgb;
  const Image surface = render_painting(painting, flat);
  if (!settings.cracks) {
    // Cracks off: the cells magnified as they are.
    const paintcore::Canvas blank(painting.canvas().spec());
    return render_crack_close_up(blank, surface, surface, region, pixels_per_cell, {}, {});
  }
  // What cracks through the film show: the bare canvas (the same ground and weave), lit
  // without the relief's shadows and occlusion, as the GPU shades it from its normal alone,
  // and through the painting's palette as there (its wavelength rule is trained on its
  // pigments: a painting without them would have another).
  RenderSettings bare = flat;
  bare.shadows = bare.occlusion = false;
  TileRenderer bare_renderer(bare, SpectralPalette(bare, painting));
  bare_renderer.render_all(paintcore::Canvas(painting.canvas().spec()));
  const Image ground = bare_renderer.image();
  Image walls = surface;
  const paintcore::Canvas& canvas = painting.canvas();
  for (int y = 0; y < canvas.height_cells(); ++y) {
    for (int x = 0; x < canvas.width_cells(); ++x) {
      const int tile = (y / paintcore::kTileSize) * canvas.tiles_x() + x / paintcore::kTileSize;
      const paintcore::CrackTile* t = canvas.cracks().tile(tile);
      if (t == nullptr) continue;
      const auto& r = t->cells[static_cast<std::size_t>(
          (y % paintcore::kTileSize) * paintcore::kTileSize + x % paintcore::kTileSize)];
      if (r.has_crack() && r.exposed_layer == paintcore::kCrackExposesGround) {
        std::copy_n(ground.pixel(x, y), 3, walls.pixel(x, y));
      }
    }
  }
  return render_crack_close_up(canvas, surface, walls, region, pixels_per_cell,
                               close_up_light(settings), {});
}

CloseUpLight close_up_light(const RenderSettings& settings) {
  const double az = settings.light_azimuth_deg * std::numbers::pi / 180.0;
  const double el = settings.light_elevation_deg * std::numbers::pi / 180.0;
  CloseUpLight light;
  light.toward_light = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  light.angular_radius_rad = 0.5 * settings.light_size_deg * std::numbers::pi / 180.0;
  light.sky_fraction = std::clamp(settings.ambient, 0.0, 1.0);
  return light;
}

void render_painting_close_up_to_file(const paintcore::Painting& painting,
                                      const RenderSettings& settings, const CellRegion& region,
                                      int pixels_per_cell, const std::filesystem::path& path) {
  image_file_type(path);  // before the work: a bad name fails fast
  write_close_up_image(render_painting_close_up(painting, settings, region, pixels_per_cell), path);
}

void write_close_up_image(Image image, const std::filesystem::path& path) {
  if (image_file_type(path) == ImageFileType::exr) {
    write_exr(path, image);
    return;
  }
  for (float& v : image.rgb) v = static_cast<float>(srgb_encoded(v));
  write_png(path, image);
}

CellRegion parse_cell_region(std::string_view text, std::string_view option) {
  int v[4] = {0, 0, 0, 0};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 4; ++i) {
    const auto [next, ec] = std::from_chars(p, end, v[i]);
    const bool last = i == 3;
    if (ec != std::errc{} || (last ? next != end : (next == end || *next != ','))) {
      throw std::runtime_error(std::string(option) + " " + std::string(text) +
                               ": expected X,Y,W,H in cells, e.g. 10,20,8,6");
    }
    p = last ? next : next + 1;
  }
  // Within a canvas's reach, so that x + w and the like cannot overflow.
  constexpr int kMax = paintcore::kMaxCanvasCells;
  const char* names[4] = {"X", "Y", "W", "H"};
  for (int i = 0; i < 4; ++i) {
    const int lo = i < 2 ? -kMax : 1;
    if (v[i] < lo || v[i] > kMax)
      throw std::runtime_error(std::string(option) + " " + std::string(text) + ": " + names[i] +
                               " " + std::to_string(v[i]) + " is outside " + std::to_string(lo) +
                               ".." + std::to_string(kMax));
  }
  return {v[0], v[1], v[2], v[3]};
}

}  // namespace impasto::render
