#include "bench_surface_gpu.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include <impasto/render_gl/canvas_renderer.hpp>
#include <impasto/render_gl/framebuffer.hpp>
#include <impasto/render_gl/gl_context.hpp>

namespace impasto::app {

namespace {

// Best of three of an upload of every tile (with the spread on, each tile's map) and a draw of
// the whole canvas at a pixel a cell, finished; after one untimed draw (the shader's compile).
double upload_and_draw_ns_per_cell(const paintcore::Canvas& canvas,
                                   const render::RenderSettings& settings,
                                   const render::SpectralPalette& palette, int* mapped) {
  const int w = canvas.width_cells(), h = canvas.height_cells();
  render_gl::CanvasRenderer renderer(w, h, settings, palette);
  render_gl::Framebuffer target(w, h, render_gl::TexelFormat::kRGBA32F);
  const auto draw = [&] {
    renderer.upload_all(canvas);
    target.bind();
    renderer.draw(render_gl::one_pixel_per_cell(w, h), w, h);
    glFinish();
  };
  draw();
  double best = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 3; ++trial) {
    const auto start = std::chrono::steady_clock::now();
    draw();
    best = std::min(
        best,
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
  }
  if (mapped != nullptr) *mapped = renderer.subsurface_cells();
  return best / (static_cast<double>(w) * h);
}

}  // namespace

GpuSpreadCost gpu_spread_cost(const paintcore::Canvas& spreading, const paintcore::Canvas& plain,
                              const render::RenderSettings& settings,
                              const render::SpectralPalette& palette) {
  auto context = render_gl::create_headless_context();
  render::RenderSettings off = settings;
  off.surface.subsurface = false;
  render::RenderSettings on = settings;
  on.surface.subsurface = true;
  GpuSpreadCost cost;
  cost.spreading_off = upload_and_draw_ns_per_cell(spreading, off, palette, nullptr);
  cost.spreading_on = upload_and_draw_ns_per_cell(spreading, on, palette, &cost.spreading_cells);
  cost.plain_off = upload_and_draw_ns_per_cell(plain, off, palette, nullptr);
  cost.plain_on = upload_and_draw_ns_per_cell(plain, on, palette, nullptr);
  return cost;
}

}  // namespace impasto::app
