#include "impasto/render_gl/render_painting_gpu.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"

namespace impasto::render_gl {

render::Image draw_to_image(CanvasRenderer& renderer, const CanvasView& view, int width,
                            int height) {
  Framebuffer target(width, height, TexelFormat::kRGBA32F);
  target.bind();
  renderer.draw(view, width, height);
  const std::vector<float> rgba = target.read_rgba_float();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  render::Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
  for (int y = 0; y < height; ++y) {
    const float* row =
        rgba.data() + static_cast<size_t>(height - 1 - y) * width * 4;  // GL: bottom row first
    for (int x = 0; x < width; ++x) {
      float* out = image.pixel(x, y);
      out[0] = row[4 * x];
      out[1] = row[4 * x + 1];
      out[2] = row[4 * x + 2];
    }
  }
  return image;
}

render::Image render_canvas_in_current_context(const paintcore::Canvas& canvas,
                                               const render::RenderSettings& settings,
                                               render::SpectralPalette palette) {
  const int width = canvas.width_cells();
  const int height = canvas.height_cells();
  CanvasRenderer renderer(width, height, settings, std::move(palette));
  renderer.upload_all(canvas);
  return draw_to_image(renderer, one_pixel_per_cell(width, height), width, height);
}

render::Image render_painting_close_up_gpu(const paintcore::Painting& painting,
                                           const render::RenderSettings& settings,
                                           const render::CellRegion& region, int pixels_per_cell,
                                           HeadlessBackend backend) {
  const paintcore::Canvas& canvas = painting.canvas();
  render::check_close_up_region(region, pixels_per_cell, canvas.width_cells(),
                                canvas.height_cells());
  // Linear sRGB, as the CPU close-up returns it.
  render::RenderSettings linear = settings;
  linear.display = render::DisplayEncoding::linear_srgb;
  auto context = create_headless_context(backend);
  GpuViewOptions options;
  options.crack_close_up_min_pixels = 1.0f;  // shown at any zoom, as the CPU's --zoom does
  options.smooth_zoom = false;               // cells magnified, as the CPU's close-up shows them
  CanvasRenderer renderer(canvas.width_cells(), canvas.height_cells(), linear,
                          render::SpectralPalette(linear, painting), options);
  renderer.upload_all(canvas);
  const CanvasView view{region.x + 0.5 * region.w, region.y + 0.5 * region.h,
                        static_cast<double>(pixels_per_cell), 0.0};
  return draw_to_image(renderer, view, region.w * pixels_per_cell, region.h * pixels_per_cell);
}

void render_painting_close_up_gpu_to_file(const paintcore::Painting& painting,
                                          const render::RenderSettings& settings,
                                          const render::CellRegion& region, int pixels_per_cell,
                                          const std::filesystem::path& path,
                                          HeadlessBackend backend) {
  render::image_file_type(path);  // before the work: a bad name fails fast
  render::write_close_up_image(
      render_painting_close_up_gpu(painting, settings, region, pixels_per_cell, backend), path);
}

render::Image render_painting_gpu(const paintcore::Canvas& canvas,
                                  const render::RenderSettings& settings,
                                  render::SpectralPalette palette, HeadlessBackend backend) {
  auto context = create_headless_context(backend);
  return render_canvas_in_current_context(canvas, settings, std::move(palette));
}

render::Image render_painting_gpu(const paintcore::Canvas& canvas,
                                  std::span<const std::string> pigment_slots,
                                  const render::RenderSettings& settings, HeadlessBackend backend) {
  return render_painting_gpu(canvas, settings, render::SpectralPalette(settings, pigment_slots),
                             backend);
}

void render_painting_gpu_to_file(const paintcore::Painting& painting,
                                 const render::RenderSettings& settings,
                                 const std::filesystem::path& path, HeadlessBackend backend) {
  const render::ImageFileType type = render::image_file_type(path);
  if (settings.wavelengths == 0) {
    throw std::runtime_error(path.string() +
                             ": the GPU path takes 1..16 wavelength nodes, not the full "
                             "spectrum (render without --gpu)");
  }
  // EXR holds linear values, as the CPU path writes them.
  render::RenderSettings file_settings = settings;
  if (type == render::ImageFileType::exr)
    file_settings.display = render::DisplayEncoding::linear_srgb;
  const render::Image image = render_painting_gpu(
      painting.canvas(), file_settings, render::SpectralPalette(file_settings, painting), backend);
  if (type == render::ImageFileType::png) {
    render::write_png(path, image);
  } else {
    render::write_exr(path, image);
  }
}

}  // namespace impasto::render_gl
