#include "impasto/render/render_painting.hpp"

#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

Image render_painting(const paintcore::Painting& painting, const RenderSettings& settings) {
  TileRenderer renderer(settings, painting.pigment_slots());
  renderer.render_all(painting.canvas());
  return renderer.image();
}

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path) {
  if (image_file_type(path) == ImageFileType::png) {
    write_png(path, render_painting(painting, settings));
  } else {
    RenderSettings linear = settings;
    linear.display = DisplayEncoding::linear_srgb;
    write_exr(path, render_painting(painting, linear));
  }
}

}  // namespace impasto::render
