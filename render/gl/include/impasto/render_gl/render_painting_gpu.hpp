#pragma once
// `impasto render --gpu`: a whole canvas rendered headless through the GLSL shaders, one
// pixel per cell, in the same Image form as the CPU's render::TileRenderer::image().
#include <span>
#include <string>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
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

// Renders into the current context (no context made): for callers that keep one.
render::Image render_canvas_in_current_context(const paintcore::Canvas& canvas,
                                               const render::RenderSettings& settings,
                                               render::SpectralPalette palette);

}  // namespace impasto::render_gl
