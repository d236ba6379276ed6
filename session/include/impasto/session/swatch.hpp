#pragma once
// The Palette panel's swatch: the mix as it will lie on the canvas, found the honest way. A
// standard stroke with the window's brush, load and pressure is painted by the simulation on
// a small painting at the canvas's DPI and weave, and rendered by the CPU reference renderer
// (render::TileRenderer) under the current light; the chip is the mean colour over the
// stroke's area. Beside it, the masstone: an opaque flat layer of the mix, rendered the same way.
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/render_settings.hpp>
#include <impasto/render/spectral_sampling.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace impasto::session {

// Everything the deposit depends on; equal strokes deposit the same paint.
struct SwatchStroke {
  input::BrushEvent brush;  // as the window sends it to the painting
  input::LoadEvent load;    // the mix and the volume, loaded onto a clean brush
  float pressure = 0.6f;
  double dpi = 150.0;            // the painting's
  std::uint64_t weave_seed = 1;  // the painting's canvas (0: flat)
  bool operator==(const SwatchStroke&) const = default;
};

// The standard stroke: a straight line of max(15 mm, 3 brush widths) at 50 mm/s, a pen sample
// every 0.2 mm at the stroke's pressure, starting `origin_mm` from the painting's top left.
// Painted through app::SessionPlayer, the path a live session takes.
void paint_standard_stroke(paintcore::Painting& painting, const SwatchStroke& stroke,
                           double origin_x_mm, double origin_y_mm);
// The standard stroke on a fresh painting just large enough for it and the brush around it,
// at swatch_dpi(): the canvas's, or coarser where the brush would be more than 128 cells
// across (the simulation's deposit does not depend on the resolution, and a 60 mm brush at
// 150 dpi would cost some 20 s instead of a fraction of one).
paintcore::Painting paint_swatch_stroke(const SwatchStroke& stroke);
double swatch_dpi(const SwatchStroke& stroke);

// Cells holding more wet paint than this are painted; less is a stroke's smear (the threshold
// of Painting::paint_thickness and `impasto replay --stats`).
inline constexpr float kPaintedAboveMm = 1e-3f;

// The cells a stroke painted and the median of their wet thickness.
struct Deposit {
  std::size_t painted_cells = 0;
  double median_mm = 0.0;
};
Deposit wet_deposit(const paintcore::Painting& painting);

using DisplayRgb = std::array<float, 3>;  // as the renderer writes it under settings.display
// The colour within [0, 1] each, as a chip or a colour button shows it.
inline DisplayRgb clamped(const DisplayRgb& rgb) {
  return {std::clamp(rgb[0], 0.0f, 1.0f), std::clamp(rgb[1], 0.0f, 1.0f),
          std::clamp(rgb[2], 0.0f, 1.0f)};
}

// The area of strokes painted along x: in each column, the cells from the first to the last
// painted one, so the skips between bristles count as the eye sees them, part of the stroke.
// One flag per cell, row-major.
std::vector<std::uint8_t> stroke_area(const paintcore::Canvas& canvas);
// The painting rendered by render::TileRenderer, and the mean colour over stroke_area(),
// taken in linear light and encoded for settings.display. The ground's colour when nothing
// is painted. Each function here renders with the rule settings ask for for its pigments,
// or, given `rule` (the painting's own: CanvasViewer's palette), with that one, so a chip
// shows a paint as the canvas will.
DisplayRgb mean_stroke_colour(const paintcore::Painting& painting,
                              const render::RenderSettings& settings,
                              const render::SpectralSampling* rule = nullptr);

// Flat, uniform layers over the flat canvas ground, rendered by render::TileRenderer: one
// colour per mix, each a layer of `thickness_mm` (pigment names from the default database,
// any parts).
std::vector<DisplayRgb> render_flat_layers(const render::RenderSettings& settings,
                                           std::span<const std::vector<input::PigmentPart>> mixes,
                                           double thickness_mm,
                                           const render::SpectralSampling* rule = nullptr);
// A layer thick enough to hide anything beneath it: the masstone (optical thickness 1e4).
double masstone_thickness_mm(const render::RenderSettings& settings);

struct Swatch {
  DisplayRgb on_canvas{};  // the standard stroke as rendered
  DisplayRgb masstone{};   // an opaque layer of the mix
  Deposit deposit;         // what the stroke left
};

// Paints the standard stroke and renders both chips. Throws std::runtime_error (naming the
// problem) for an empty mix, unknown pigments, bad brush or light settings.
Swatch make_swatch(const SwatchStroke& stroke, const render::RenderSettings& settings,
                   const render::SpectralSampling* rule = nullptr);

}  // namespace impasto::session
