#pragma once
// impasto bench surface's GPU line: what the subsurface spread costs the OpenGL canvas pass
// (render_gl/subsurface_spread.hpp), on a painting where it applies and on one where nothing
// spreads, each with the spread on and off.
#include <impasto/paintcore/canvas.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <optional>

namespace impasto::app {

struct GpuSpreadCost {
  // ns per cell of an upload of every tile and one draw at a pixel a cell (best of three).
  double spreading_off = 0.0, spreading_on = 0.0;  // the painting where light spreads
  double plain_off = 0.0, plain_on = 0.0;          // the painting where nothing spreads
  int spreading_cells = 0;                         // cells the GPU's map holds
};

// Empty when this build has no OpenGL path. `settings`: the ghs surface (the spread is
// switched on and off here).
std::optional<GpuSpreadCost> gpu_spread_cost(const paintcore::Canvas& spreading,
                                             const paintcore::Canvas& plain,
                                             const render::RenderSettings& settings,
                                             const render::SpectralPalette& palette);

}  // namespace impasto::app
