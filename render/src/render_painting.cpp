#include "impasto/render/render_painting.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

Image render_painting(const paintcore::Painting& painting, const RenderSettings& settings) {
  TileRenderer renderer(settings, painting.pigment_slots());
  renderer.render_all(painting.canvas());
  return renderer.image();
}

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".png") {
    write_png(path, render_painting(painting, settings));
  } else if (extension == ".exr") {
    RenderSettings linear = settings;
    linear.display = DisplayEncoding::linear_srgb;
    write_exr(path, render_painting(painting, linear));
  } else {
    throw std::runtime_error(path.string() + ": unknown image type '" + extension +
                             "' (expected .png or .exr)");
  }
}

}  // namespace impasto::render
