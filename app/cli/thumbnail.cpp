#include "thumbnail.hpp"

#include <impasto/paintcore/painting.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace impasto::app {

render::Image shrink_to_fit(const render::Image& image, int max_side) {
  if (max_side < 1) throw std::runtime_error("thumbnail size must be at least 1 pixel");
  const int longer = std::max(image.width, image.height);
  if (longer <= max_side) return image;
  const double scale = static_cast<double>(max_side) / longer;
  render::Image out;
  out.width = std::max(1, static_cast<int>(std::lround(image.width * scale)));
  out.height = std::max(1, static_cast<int>(std::lround(image.height * scale)));
  out.rgb.assign(3 * static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height),
                 0.0f);
  for (int y = 0; y < out.height; ++y) {
    // The input rows [y0, y1) and columns [x0, x1) this pixel covers (at least one each).
    const int y0 = y * image.height / out.height;
    const int y1 = std::max(y0 + 1, (y + 1) * image.height / out.height);
    for (int x = 0; x < out.width; ++x) {
      const int x0 = x * image.width / out.width;
      const int x1 = std::max(x0 + 1, (x + 1) * image.width / out.width);
      double sum[3] = {0.0, 0.0, 0.0};
      for (int v = y0; v < y1; ++v) {
        for (int u = x0; u < x1; ++u) {
          for (int c = 0; c < 3; ++c) sum[c] += image.pixel(u, v)[c];
        }
      }
      const double count = static_cast<double>((y1 - y0) * (x1 - x0));
      for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = static_cast<float>(sum[c] / count);
    }
  }
  return out;
}

int thumbnail_coarsening(const paintcore::CanvasSpec& spec, int size) {
  const int longer = std::max(spec.width_cells, spec.height_cells);
  const int by_size = longer / (2 * std::max(size, 1));
  return std::max(1, std::min(by_size, static_cast<int>(spec.dpi)));  // dpi stays >= 1
}

void write_thumbnail(const std::filesystem::path& painting_path, const std::filesystem::path& png,
                     int size) {
  if (size < 1) throw std::runtime_error("thumbnail size must be at least 1 pixel");
  const paintcore::Painting full =
      paintcore::Painting::load(painting_path, 0, false);  // no undo history: not drawn
  // Rendered at about twice the thumbnail's size, not the canvas's: a 16384-cell painting
  // took minutes and gigabytes at full size for a picture of 256 pixels.
  const int factor = thumbnail_coarsening(full.canvas().spec(), size);
  const std::optional<paintcore::Painting> coarse =
      factor > 1 ? std::optional(full.coarsened(factor)) : std::nullopt;
  const paintcore::Painting& painting = coarse ? *coarse : full;
  render::check_render_memory(painting.canvas(), painting_path.string());
  // The Gaussian rule: a file manager's thumbnailer runs once per file, often where no cache
  // can be kept, and a palette's trained rule (up to a second to build) shows no difference
  // at thumbnail size.
  render::RenderSettings settings;
  settings.node_weights = render::NodeWeights::interpolatory;
  render::write_png(png, shrink_to_fit(render::render_painting(painting, settings), size));
}

}  // namespace impasto::app
