#pragma once
// impasto bench surface's GPU line: what the subsurface spread costs the OpenGL canvas pass
// (render_gl/subsurface_spread.hpp), on a painting where it applies and on one where nothing
// spreads, each with the spread on and off.
#include <impasto/paintcore/canvas.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_palette.hpp>

#include "window_services.hpp"

namespace impasto::app {

// `settings`: the ghs surface (the spread is switched on and off here).
GpuSpreadCost gpu_spread_cost(const paintcore::Canvas& spreading, const paintcore::Canvas& plain,
                              const render::RenderSettings& settings,
                              const render::SpectralPalette& palette);

}  // namespace impasto::app
