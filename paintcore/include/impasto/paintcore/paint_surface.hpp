#pragma once
// The finish of the paint's surface as part of the paint (docs/surface.md, "Medium and
// varnish in the painting"): the medium a mix was made with, carried by the paint into the
// cells it is laid in, and varnish coats over the painting or part of it. paintcore keeps,
// mixes and dries them; the renderer turns them into the GHS surface per cell
// (render/surface_shading.hpp), the window's GLSL port reads the same cells through
// cell_surface().
//
// Per cell, only in tiles that have them (Tile::medium, Tile::varnish are empty elsewhere, so
// a painting without media or varnish costs nothing and renders as before).
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "impasto/paintcore/canvas.hpp"

namespace impasto::paintcore {

// The finishes a medium or a varnish dries to.
enum class Finish : std::uint8_t { gloss, satin, matte };
inline constexpr int kFinishCount = 3;
// Their spellings (stroke files, the command line, the painting's summary).
inline constexpr std::array<std::string_view, kFinishCount> kFinishSpellings{"gloss", "satin",
                                                                             "matte"};
constexpr std::string_view finish_name(Finish finish) {
  return kFinishSpellings[static_cast<std::size_t>(finish)];
}

// RMS height and correlation length (µm) of a film's micro-roughness.
struct FinishRoughness {
  double rms_um = 0.0;
  double correlation_um = 1.0;
};
// The film of each finish (docs/surface.md: chosen so that 60° specular gloss falls in the
// ranges paint makers state for each).
FinishRoughness film_roughness(Finish finish);
double finish_log_rms(Finish finish);  // log10 of rms_um
// A roughness between the finishes, by its log10 RMS: the correlation length follows the
// gloss–satin–matte curve (geometric between neighbours, held beyond the ends), so one number
// per cell describes the surface.
FinishRoughness roughness_at_log_rms(double log_rms);
// The range a cell's log10 RMS may take (a file's values are checked against it).
inline constexpr double kMinLogRms = -3.0;
inline constexpr double kMaxLogRms = 1.0;

// The medium a mix is made with: its finish and how much of the paint it is, 0 (paint
// straight from the tube, which dries satin) to 1 (the medium's own finish); between, the
// roughness is interpolated geometrically (as render::SurfaceSettings's medium).
struct Medium {
  Finish finish = Finish::gloss;
  double amount = 1.0;
};
void validate(const Medium& medium);  // throws std::runtime_error naming the field
double medium_log_rms(const Medium& medium);
std::string medium_spelling(const Medium& medium);  // what parse_medium reads back

// Inline: the stroke files' reader (input) takes paintcore's headers, not its library.
inline std::optional<Finish> finish_from_name(std::string_view name) {
  for (int k = 0; k < kFinishCount; ++k)
    if (kFinishSpellings[static_cast<std::size_t>(k)] == name) return static_cast<Finish>(k);
  return std::nullopt;
}

// "matte" (amount 1) or "matte:0.5"; throws std::runtime_error saying what is wrong.
inline Medium parse_medium(std::string_view text) {
  const auto colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  const std::optional<Finish> finish = finish_from_name(name);
  if (!finish)
    throw std::runtime_error("unknown finish '" + std::string(name.substr(0, 32)) +
                             "' (known: gloss, satin, matte)");
  Medium medium{*finish, 1.0};
  if (colon != std::string_view::npos) {
    const std::string amount(text.substr(colon + 1, 32));
    std::size_t used = 0;
    try {
      medium.amount = std::stod(amount, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != amount.size() || !(medium.amount >= 0.0 && medium.amount <= 1.0))
      throw std::runtime_error("the amount of medium '" + amount + "' is not a number in [0, 1]");
  }
  return medium;
}

// The medium a volume of paint carries: the share of that paint mixed with a medium (0: none
// set, the render settings' medium decides, as in paintings made before media existed) and
// the log10 RMS roughness that share dries to.
struct PaintMedium {
  float share = 0.0f;
  float log_rms = 0.0f;
  bool operator==(const PaintMedium&) const = default;
};
PaintMedium paint_medium(const Medium& medium);  // share 1
// The medium to load so that new paint dries as `paint` does (the eyedropper's pick): none
// where less than half the paint holds a medium; else the finish on the side of tube paint
// (satin) its roughness lies, and the amount that gives that roughness (medium_log_rms).
std::optional<Medium> loadable_medium(const PaintMedium& paint);
// Two volumes of paint mixed: shares by volume, roughness by the volume of medium in log
// space (amount-weighted geometric mean of the RMS heights).
PaintMedium mix(const PaintMedium& a, double a_volume, const PaintMedium& b, double b_volume);

// Paint laid on a cell mixes with the surface already there: its wet paint and at most this
// depth of the dry paint under it, so a thin film over dry paint takes over only part of its
// finish, and the first paint on the bare ground all of it.
inline constexpr double kSurfaceFilmMm = 0.01;

// Varnish coats: thickness in mm of paint height, kMinVarnishMm to kMaxVarnishMm a coat, one
// range wherever a thickness is accepted (the stroke file, `edit`, the window, the engine).
// Thinner than a tenth of a micrometre a coat does nothing a render shows.
inline constexpr double kMinVarnishMm = 1e-4;
inline constexpr double kMaxVarnishMm = 1.0;
// A coat flows before it sets, from the peaks of the relief under it into its valleys
// (docs/surface.md, "Varnish"): each cell's coat is the thickness plus levelled_share of the
// way from the surface there to its mean within kVarnishLevellingMm, the share growing with
// the cube of the thickness (a film's levelling rate goes as h^3, Orchard 1962) and half at
// kVarnishHalfLevelledMm. The coat's volume is kept. A varnish wets what it is brushed over:
// a peak keeps a film of at least kVarnishWettingShare of the thickness (the coat over a
// region varnishes every cell of it).
inline constexpr double kVarnishLevellingMm = 0.25;
inline constexpr double kVarnishHalfLevelledMm = 0.05;
inline constexpr double kVarnishWettingShare = 0.2;
double varnish_levelled_share(double thickness_mm);

// The planes of a tile's surface data (plane-major, kTileCells values each).
inline constexpr int kMediumPlanes = 2;   // share, log_rms
inline constexpr int kVarnishPlanes = 3;  // thickness_mm, wet_mm, log_rms

// What one cell's surface holds: the medium of its top paint and its varnish (the varnish,
// when there is one, is the surface the light meets).
struct CellSurface {
  PaintMedium medium;
  float varnish_mm = 0.0f;      // 0: not varnished
  float varnish_wet_mm = 0.0f;  // the part not yet dried (a wet varnish is glossy)
  float varnish_log_rms = 0.0f;
  bool varnished() const { return varnish_mm > 0.0f; }
  // 0 (dry) .. 1 (just applied).
  float varnish_wetness() const { return varnished() ? varnish_wet_mm / varnish_mm : 0.0f; }
};

// The height (mm) of the surface the light meets at cell `cell` of a tile: the ground, the
// dry and wet paint, and a varnish over them. Every renderer's relief reads this.
inline float surface_height_mm(const Tile& tile, int cell) {
  const auto c = static_cast<std::size_t>(cell);
  const float paint = tile.base_height_mm[c] + tile.dry_height_mm[c] + tile.wet_volume_mm[c];
  return tile.varnish.empty() ? paint : paint + tile.varnish[c];
}
// The same at canvas cell (x, y) (inside the canvas; a tile never painted is its weave).
inline float surface_height_mm(const Canvas& canvas, int x, int y) {
  const Tile* tile = canvas.tile(x / kTileSize, y / kTileSize);
  return tile != nullptr ? surface_height_mm(*tile, (y % kTileSize) * kTileSize + x % kTileSize)
                         : canvas.base_height_mm(x, y);
}

// The surface of cell `cell` (local index) of a tile; a null tile or one without surface data
// gives the default (no medium, no varnish).
CellSurface cell_surface(const Tile* tile, int cell);
// Whether a tile holds any medium or varnish data (a renderer's per-tile shortcut).
inline bool has_surface(const Tile* tile) {
  return tile != nullptr && (!tile->medium.empty() || !tile->varnish.empty());
}
// Copies one cell's medium and varnish from `from` (null or without data: nothing) to `to`,
// making `to`'s planes when needed: a crop, a resize or a finer canvas keeps the surface with
// the paint.
void copy_cell_surface(const Tile* from, int from_cell, Tile& to, int to_cell);
// Pointers to a plane of a tile's data (nullptr when the tile has none).
inline const float* medium_plane(const Tile& tile, int plane) {
  return tile.medium.empty() ? nullptr : tile.medium.data() + plane * kTileCells;
}
inline const float* varnish_plane(const Tile& tile, int plane) {
  return tile.varnish.empty() ? nullptr : tile.varnish.data() + plane * kTileCells;
}

}  // namespace impasto::paintcore
