#pragma once
// What the command line borrows from the libraries only the window target links (OpenGL,
// ImGui's font): that target provides them as the program starts (window/window_services.cpp);
// an impasto built without the OpenGL path leaves them empty and the commands say so. So the
// command line never includes a GL, GLFW or ImGui header.
#include <impasto/paintcore/canvas.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/crack_close_up.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace impasto::app {

// impasto bench surface's GPU line: what the subsurface spread costs the OpenGL canvas pass,
// on a painting where it applies and on one where nothing spreads, each with it on and off.
struct GpuSpreadCost {
  // ns per cell of an upload of every tile and one draw at a pixel a cell (best of three).
  double spreading_off = 0.0, spreading_on = 0.0;  // the painting where light spreads
  double plain_off = 0.0, plain_on = 0.0;          // the painting where nothing spreads
  int spreading_cells = 0;                         // cells the GPU's map holds
};

struct WindowServices {
  // `render --gpu`: the painting, or a region of it close up, rendered by OpenGL to a file.
  std::function<void(const paintcore::Painting&, const render::RenderSettings&,
                     const std::filesystem::path&)>
      render_painting;
  std::function<void(const paintcore::Painting&, const render::RenderSettings&,
                     const render::CellRegion&, int pixels_per_cell, const std::filesystem::path&)>
      render_close_up;
  // `settings`: the ghs surface (the spread is switched on and off inside).
  std::function<GpuSpreadCost(const paintcore::Canvas& spreading, const paintcore::Canvas& plain,
                              const render::RenderSettings& settings,
                              const render::SpectralPalette& palette)>
      spread_cost;
  // The pixels of a plot's label in ImGui's built-in font, its left end (or its middle, when
  // centred) at x and its baseline at y: plot(x, y, coverage in [0, 1]) for each.
  std::function<void(const std::string& text, double x, double y, bool centred,
                     const std::function<void(int, int, double)>& plot)>
      text_pixels;
};

// The services provided, or nullptr in a build without the window target.
const WindowServices* window_services();
void provide_window_services(WindowServices services);

// What `--gpu` says in a build without the OpenGL path.
inline constexpr const char* kNoGpuPath = "this impasto was built without the OpenGL path";

}  // namespace impasto::app
