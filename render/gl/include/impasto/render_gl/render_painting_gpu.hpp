#pragma once
// `impasto render --gpu`: a whole canvas rendered headless through the GLSL shaders, one
// pixel per cell, in the same Image form as the CPU's render::TileRenderer::image().
#include <filesystem>
#include <span>
#include <string>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/crack_close_up.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl {

// Pigment i of the palette is painting slot i. Creates (and releases) a headless context;
// throws std::runtime_error when none can be made or the canvas exceeds the GPU's limits.
render::Image render_painting_gpu(const paintcore::Canvas& canvas,
                                  const render::RenderSettings& settings,
                                  render::SpectralPalette palette,
                                  HeadlessBackend backend = HeadlessBackend::kAuto);

// The same with the palette built from the default pigment database by slot name.
render::Image render_painting_gpu(const paintcore::Canvas& canvas,
                                  std::span<const std::string> pigment_slots,
                                  const render::RenderSettings& settings,
                                  HeadlessBackend backend = HeadlessBackend::kAuto);

// `impasto render --gpu`: render::render_painting_to_file through the shaders. Writes by
// extension: .png (8-bit, settings.display) or .exr (linear sRGB primaries). Throws
// std::runtime_error naming the file for another extension, and for settings the shaders do
// not take (full-spectrum rendering).
void render_painting_gpu_to_file(const paintcore::Painting& painting,
                                 const render::RenderSettings& settings,
                                 const std::filesystem::path& path,
                                 HeadlessBackend backend = HeadlessBackend::kAuto);

// `impasto render --gpu --zoom P --region R`: the close-up (render::render_painting_close_up)
// through the window's canvas pass, seen at P pixels per cell: linear sRGB, region.w P x
// region.h P pixels. Throws std::runtime_error for a region outside the canvas, P outside
// 1..256, or an image beyond the GPU's limits.
render::Image render_painting_close_up_gpu(const paintcore::Painting& painting,
                                           const render::RenderSettings& settings,
                                           const render::CellRegion& region, int pixels_per_cell,
                                           HeadlessBackend backend = HeadlessBackend::kAuto);
// The same written as render::write_close_up_image writes it.
void render_painting_close_up_gpu_to_file(const paintcore::Painting& painting,
                                          const render::RenderSettings& settings,
                                          const render::CellRegion& region, int pixels_per_cell,
                                          const std::filesystem::path& path,
                                          HeadlessBackend backend = HeadlessBackend::kAuto);

// Draws the canvas through `view` into a width x height float target in the current context
// and reads it back as an Image (rows top-down; the renderer's display encoding).
render::Image draw_to_image(CanvasRenderer& renderer, const CanvasView& view, int width,
                            int height);

// Renders into the current context (no context made): for callers that keep one.
render::Image render_canvas_in_current_context(const paintcore::Canvas& canvas,
                                               const render::RenderSettings& settings,
                                               render::SpectralPalette palette);

}  // namespace impasto::render_gl
