#pragma once
// Light that enters the paint at one cell and leaves at another (docs/surface.md): where the
// top layer's diffusion length (dipole.hpp, from its K and S) exceeds a fraction of a cell,
// the body's light is spread over the neighbours by the dipole's profile; everywhere else
// nothing is done and nothing is paid. Per linear-sRGB channel, each with the transport
// coefficients of the nodes it sees. The surface's reflection is not spread: it is rendered
// apart (SurfaceSettings::reflection off) and added back.
#include <array>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render/dipole.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render {

// The farthest a cell's light is spread, in cells (the kernel is (2R+1)² cells).
inline constexpr int kSubsurfaceMaxRadius = 8;
// The debug view's full scale: a spread length of this many cells shows at full intensity.
inline constexpr float kSubsurfaceMapFullScaleCells = 4.0f;

// A cell whose light spreads: its top layer per channel, and how far (cells).
struct SpreadingCell {
  int x = 0, y = 0;
  std::array<dipole::Medium, 3> medium;  // per linear-sRGB channel
  std::array<float, 3> length_cells{};   // spread_length_mm / cell
  float layer_mm = 0.0f;
};

struct SubsurfaceMap {
  int width = 0, height = 0;
  double cell_mm = 0.0;
  std::vector<SpreadingCell> cells;  // only those above the threshold, row-major order
};

// Where the spread applies for these settings (empty unless the ghs model with subsurface).
SubsurfaceMap subsurface_map(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                             const RenderSettings& settings);
// The same for the cells of `region` only (clipped to the canvas): a tile the window's
// renderer uploads again.
SubsurfaceMap subsurface_map(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                             const RenderSettings& settings, const paintcore::CellRect& region);

// How far light spreads in a top layer `layer_mm` thick. A layer that scatters little
// (its K-M scattering (4/3) S d < 1, a glaze) is clear: light crosses it to what lies beneath and
// comes back up within about its thickness. A scattering layer: the dipole's diffusion length, at
// most the layer's thickness.
bool is_clear_layer(const dipole::Medium& medium, double layer_mm);
double spread_length_mm(const dipole::Medium& medium, double layer_mm);

// The normalised weights of one cell's spread over offsets −R..R each way (row-major,
// (2R+1)² values summing to 1), the centre keeping what the profile leaves inside its own
// cell. Clear layers: a Lambertian ground seen through the layer, P(r) = d²/(π(r² + d²)²),
// out to the escape cone's edge (the rest is reflected back inside); scattering layers: the
// dipole profile R_d(r) out to six spread lengths. A length far below a cell gives R = 0 and
// the single weight 1: the K-M colour, untouched.
struct SpreadKernel {
  int radius = 0;
  std::vector<float> weights{1.0f};
  float at(int dx, int dy) const {
    return weights[static_cast<std::size_t>((dy + radius) * (2 * radius + 1) + dx + radius)];
  }
};
SpreadKernel spread_kernel(const dipole::Medium& medium, double layer_mm, double cell_mm);

// Spreads each mapped cell's light of `body` (linear RGB) into `out` (which holds the same
// image, or the whole image with the body in it): out += spread(body) − body on the mapped
// cells. Light that would leave the canvas is kept in its edge cell (nothing is lost).
void apply_spread(const SubsurfaceMap& map, const Image& body, Image& out);

// The debug view: each channel's spread length, kSubsurfaceMapFullScaleCells to full scale,
// black where none.
Image subsurface_map_image(const SubsurfaceMap& map);

// The whole painting with the spread (render_painting's path for the ghs model with
// subsurface on): the full image and the body alone rendered linear, the body's light
// spread, then the display encoding. `map_out`, when given, receives the map.
Image render_painting_with_subsurface(const paintcore::Painting& painting,
                                      const RenderSettings& settings,
                                      SubsurfaceMap* map_out = nullptr);
// The same for a canvas and a palette built by the caller (tests, benchmarks).
Image render_canvas_with_subsurface(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                                    const RenderSettings& settings,
                                    SubsurfaceMap* map_out = nullptr);

}  // namespace impasto::render
