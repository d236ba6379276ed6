#include "impasto/render/render_painting.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "impasto/files/memory_budget.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/subsurface.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

void check_render_memory(const paintcore::Canvas& canvas, const std::string& where) {
  const auto cells =
      static_cast<std::uint64_t>(canvas.tiles_x()) * canvas.tiles_y() * paintcore::kTileCells;
  files::check_allocation(where,
                          "rendering the " + std::to_string(canvas.width_cells()) + " x " +
                              std::to_string(canvas.height_cells()) +
                              "-cell canvas (canvas.width_cells x canvas.height_cells)",
                          40 * cells);
}

Image render_painting(const paintcore::Painting& painting, const RenderSettings& settings,
                      const util::ProgressCallback& progress) {
  if (settings.surface.model == SurfaceModel::ghs && settings.surface.subsurface) {
    return render_painting_with_subsurface(painting, settings);  // docs/surface.md
  }
  TileRenderer renderer(settings, SpectralPalette(settings, painting));
  renderer.render_all(painting.canvas(), progress);
  return renderer.image();
}

Image render_painting_supersampled(const paintcore::Painting& painting,
                                   const RenderSettings& settings, int supersample,
                                   const util::ProgressCallback& progress) {
  if (supersample < 1 || supersample > kMaxSupersample)
    throw std::runtime_error("supersample must be 1.." + std::to_string(kMaxSupersample) +
                             ", got " + std::to_string(supersample));
  if (supersample == 1) return render_painting(painting, settings, progress);
  if (!painting.canvas().cracks().empty())  // Painting::refined does not carry them
    throw std::runtime_error(
        "supersample: the painting has cracks, which the finer canvas does not carry; render "
        "it with supersample 1");
  const paintcore::Painting fine = painting.refined(supersample);
  check_render_memory(fine.canvas(), "supersampled render");
  RenderSettings linear = settings;
  linear.display = DisplayEncoding::linear_srgb;
  const Image samples = render_painting(fine, linear, progress);
  // Each pixel the mean of its block of samples, in linear sRGB, then to XYZ for the display.
  Image image;
  image.width = painting.canvas().width_cells();
  image.height = painting.canvas().height_cells();
  image.rgb.assign(3 * static_cast<std::size_t>(image.width) * image.height, 0.0f);
  const std::array<double, 9> to_xyz = invert_3x3(xyz_to_linear_srgb());
  const double share = 1.0 / (supersample * supersample);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::array<double, 3> sum{0.0, 0.0, 0.0};
      for (int j = 0; j < supersample; ++j)
        for (int i = 0; i < supersample; ++i) {
          const float* sample = samples.pixel(x * supersample + i, y * supersample + j);
          for (int c = 0; c < 3; ++c) sum[c] += sample[c];
        }
      float* out = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        out[c] = static_cast<float>(share * (to_xyz[3 * c] * sum[0] + to_xyz[3 * c + 1] * sum[1] +
                                             to_xyz[3 * c + 2] * sum[2]));
      }
    }
  }
  DisplayTransform(settings.display).apply(image.rgb.data(), image.rgb.size() / 3);
  return image;
}

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress, int supersample) {
  if (image_file_type(path) == ImageFileType::png) {
    write_png(path, render_painting_supersampled(painting, settings, supersample, progress));
  } else {
    RenderSettings linear = settings;
    linear.display = DisplayEncoding::linear_srgb;
    write_exr(path, render_painting_supersampled(painting, linear, supersample, progress));
  }
}

}  // namespace impasto::render
