#pragma once
// One-call rendering of a whole painting to an image or a file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/util/progress.hpp"

namespace impasto::render {

// The memory a whole-canvas render takes (shaded tiles, their shading factors, heights and
// the image: 40 bytes a cell), checked against the memory budget before anything is
// allocated: a crafted 193-byte painting declaring a 131072 x 131072 canvas fails here at
// once. Throws std::runtime_error "<where>: ..." naming the canvas fields.
inline constexpr std::uint64_t kRenderBytesPerCell = 40;
void check_render_memory(const paintcore::Canvas& canvas, const std::string& where);

// Every tile of the painting rendered with `settings` (pigments from the default database,
// named by the painting's slots). progress hears of each tile shaded.
Image render_painting(const paintcore::Painting& painting, const RenderSettings& settings,
                      const util::ProgressCallback& progress = {});

// The painting rendered with supersample x supersample samples a pixel and box-filtered in
// linear light: its relief and paint refined smoothly (Painting::refined, as export --scale
// does), shaded at the finer grid, each block of samples averaged, then display-encoded. So
// relief finer than a pixel (the weave, furrows) is averaged, not aliased by the shading.
// supersample 1 is render_painting; 2 and 4 cost about 4 and 16 times as much. A cracked
// painting is refused above 1 (the finer canvas does not carry cracks).
inline constexpr int kMaxSupersample = 4;
Image render_painting_supersampled(const paintcore::Painting& painting,
                                   const RenderSettings& settings, int supersample,
                                   const util::ProgressCallback& progress = {});

// Whether the painting renders a band of rows at a time exactly as it renders whole: each band
// is the canvas cropped to its rows and the margins its shading reads (the normals, occlusion
// and shadows: relief::reach), which holds for a directional or diffuse light (a point or spot
// light is placed from the canvas's centre), without flakes (their sparkle is drawn per cell of
// the whole canvas), cracks or the subsurface spread.
bool renders_by_bands(const paintcore::Painting& painting, const RenderSettings& settings);
// The rows a band holds for a canvas `width_cells` wide: a band's render takes about
// kBandRenderBytes, whatever the canvas's height (at least one tile row, whole tile rows).
inline constexpr std::uint64_t kBandRenderBytes = 256ull << 20;
int band_rows(int width_cells);
// The painting rendered `rows` rows at a time (render_painting's image, bit for bit, where
// renders_by_bands says so): `band` hears of each band in order, top first, with the canvas row
// it starts at. Memory in proportion to a band, not the canvas. progress hears of each band's
// tiles (margins included). Throws std::runtime_error for rows under 1 or a scale outside 1..16.
// With `scale` above 1, the painting refined that many times (Painting::refined, as export
// --scale renders it), each band refined from the coarse rows it reads: `rows` are the finer
// canvas's, and no band holds more of the finer canvas than its rows and margins.
void render_painting_by_bands(const paintcore::Painting& painting, const RenderSettings& settings,
                              int rows,
                              const std::function<void(int first_row, const Image& band)>& band,
                              const util::ProgressCallback& progress = {}, int scale = 1);

// The memory render_painting_to_file takes for this painting and file: by bands where it can
// (a band's render and the file's pixels, 3 bytes a cell for PNG, 12 for OpenEXR), else the
// whole canvas at 40 bytes a cell (supersampled: the finer canvas). Checked against the
// memory budget before anything is allocated; throws std::runtime_error "<where>: ...".
void check_render_to_file_memory(const paintcore::Painting& painting,
                                 const RenderSettings& settings, const std::filesystem::path& path,
                                 int supersample, const std::string& where, int scale = 1);

// Renders and writes by extension: .png (8-bit, settings.display, sRGB by default) or .exr
// (linear sRGB primaries, full range; settings.display is ignored), by bands where
// renders_by_bands says so (the same file). `scale` above 1 renders the painting refined that
// many times (export --scale), by bands from the coarse rows each needs where it can. Throws
// std::runtime_error naming the file for another extension or a write error.
void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress = {}, int supersample = 1,
                             int scale = 1);

}  // namespace impasto::render
