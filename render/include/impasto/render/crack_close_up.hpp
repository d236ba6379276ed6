#pragma once
// Close-up view of cracks (docs/cracks.md, "Close-up rendering"). Magnified P pixels per
// cell, every pixel over a crack's opening follows the view ray into the cavity (parallax:
// the ray is cut against the cavity's profile) and shades the wall or bottom point it hits
// with that point's own view factor to the opening, the Lambert term toward the light, a soft
// shadow from the light's disc cut by the rim, and Gouffe's interreflected light. Pixels
// outside any opening keep their cell's colour. Reflectances are relative to the canvas's
// irradiance, so a flat white cell reads 1 and the far view's blend is the cell's mean.
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/crack_layer.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/util/vec3.hpp"

namespace impasto::render {

// Canvas frame: x along the columns, y down the rows, z out of the canvas (unit vectors).
using CanvasVec = util::Vec3<double>;

struct CloseUpLight {
  CanvasVec toward_light{0.0, 0.0, 1.0};  // centre of the light's disc; z > 0 lights the canvas
  double angular_radius_rad = 0.0046;     // the light's disc (the sun: 0.0046 rad)
  double sky_fraction = 0.25;             // share of the canvas irradiance from a uniform sky
  int shadow_rays = 16;                   // rays over the light's disc per shaded point
};

struct CloseUpView {
  CanvasVec toward_eye{0.0, 0.0, 1.0};  // orthographic; z > 0
};

// The close-up's light for render settings: toward the settings' light (azimuth, elevation),
// its disc of light_size_deg, the ambient share as the sky.
CloseUpLight close_up_light(const RenderSettings& settings);

// The irradiances of the close-up's sky and sun as shares of the canvas's (so that a flat
// white cell reads 1): sky_fraction and (1 - sky_fraction) / cos(zenith); a light below the
// horizon leaves the sky alone, at 1. Both renderers' close-ups shade with these.
struct CloseUpIrradiance {
  double sky = 1.0, sun = 0.0;
};
CloseUpIrradiance close_up_irradiance(const CloseUpLight& light);

// The light's shadow_rays directions over its disc (a Vogel spiral, even in solid angle),
// canvas frame; the close-up's soft shadows average over them.
std::vector<CanvasVec> close_up_light_directions(const CloseUpLight& light);

// Throws std::invalid_argument naming the field for a non-unit or backward direction, a
// sky fraction outside [0, 1], a negative radius or fewer than one shadow ray.
void validate(const CloseUpLight& light, const CloseUpView& view);

// One cell magnified to pixels_per_cell^2 pixels, row-major, `channels` values per pixel
// (channels = surface.size() = wall.size(); out.size() = P^2 * channels). `surface`: the
// cell's reflectance, `wall`: that of the layer the crack's walls expose. A groove runs
// along x when groove_along_x, else along y; a pit sits at the cell's centre. A cell
// without a crack is `surface` in every pixel. Throws std::invalid_argument on bad sizes.
void crack_close_up_cell(const paintcore::CrackRecord& record, double cell_mm, bool groove_along_x,
                         int pixels_per_cell, std::span<const float> surface,
                         std::span<const float> wall, const CloseUpLight& light,
                         const CloseUpView& view, std::span<float> out);

// A region of cells (x, y: first column and row; w, h: size in cells).
struct CellRegion {
  int x = 0, y = 0, w = 0, h = 0;
};

// The region magnified: an image of w*P x h*P pixels. `surface` holds the cells' colours
// (one pixel per cell, the canvas's size) and `walls` the colours of what their cracks
// expose; grooves run the way their cracked neighbours do (the longer run of cracked cells
// within two cells along x or along y; x on a tie). Throws std::runtime_error naming the field for
// a region outside the canvas, P outside 1..256 or images of another size.
Image render_crack_close_up(const paintcore::Canvas& canvas, const Image& surface,
                            const Image& walls, const CellRegion& region, int pixels_per_cell,
                            const CloseUpLight& light, const CloseUpView& view);

// A painting's region magnified, lit as `settings` lights it (light direction and size, the
// ambient share as the sky), seen from straight above: the cells' colours are the painting
// rendered without its cracks (linear sRGB), the walls those of the paint around them or,
// for cracks through the film, of the bare canvas. Linear sRGB. settings.cracks = false:
// the cells magnified alone.
Image render_painting_close_up(const paintcore::Painting& painting, const RenderSettings& settings,
                               const CellRegion& region, int pixels_per_cell);

// A linear sRGB close-up written by extension: .png (the sRGB curve) or .exr (linear). Throws
// std::runtime_error naming the file for another extension.
void write_close_up_image(Image image, const std::filesystem::path& path);

// render_painting_close_up written by write_close_up_image.
void render_painting_close_up_to_file(const paintcore::Painting& painting,
                                      const RenderSettings& settings, const CellRegion& region,
                                      int pixels_per_cell, const std::filesystem::path& path);

// Throws std::runtime_error naming the field for a region outside a canvas of this size or a
// zoom outside 1..256 pixels per cell.
void check_close_up_region(const CellRegion& region, int pixels_per_cell, int width_cells,
                           int height_cells);

// "X,Y,W,H" in cells, X and Y within ±kMaxCanvasCells and W, H in 1..kMaxCanvasCells;
// throws std::runtime_error naming the option and the text when malformed or out of reach.
CellRegion parse_cell_region(std::string_view text, std::string_view option = "--region");

}  // namespace impasto::render
