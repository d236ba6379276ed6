#pragma once
// What only the GPU view adds to render::RenderSettings: exposure and the colour around the
// canvas. Everything that decides how paint looks stays in RenderSettings, shared with the
// CPU reference.
#include <array>

namespace impasto::render_gl {

struct GpuViewOptions {
  float light_intensity = 1.0f;                              // exposure, 1 = as the CPU renders
  std::array<float, 3> background_rgb{0.16f, 0.16f, 0.18f};  // display RGB outside the canvas
  // Zoomed in to this many screen pixels per cell or more, cracks show their insides (the
  // close-up, docs/cracks.md); further out, their far-view blend. 0: never.
  float crack_close_up_min_pixels = 6.0f;
  // Zoomed in, colour, normal and relief light interpolated between cell centres (no cell
  // blocks); zoomed out, the shaded colours of the cells under a pixel averaged (no speckle).
  // Off: every pixel shows its own cell, as the CPU's close-up magnifies cells.
  bool smooth_zoom = true;
  // The subsurface spread's debug view (the ghs surface with its spread): where light spreads
  // sideways, each channel's length to render::kSubsurfaceMapFullScaleCells at full scale, over
  // the painting at a quarter of its light.
  bool subsurface_map = false;
};

}  // namespace impasto::render_gl
