#include "impasto/render/render_painting.hpp"

#include "impasto/files/memory_budget.hpp"
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

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress) {
  if (image_file_type(path) == ImageFileType::png) {
    write_png(path, render_painting(painting, settings, progress));
  } else {
    RenderSettings linear = settings;
    linear.display = DisplayEncoding::linear_srgb;
    write_exr(path, render_painting(painting, linear, progress));
  }
}

}  // namespace impasto::render
