#pragma once
// One-call rendering of a whole painting to an image or a file.
#include <filesystem>
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

// Renders and writes by extension: .png (8-bit, settings.display, sRGB by default) or .exr
// (linear sRGB primaries, full range; settings.display is ignored). Throws
// std::runtime_error naming the file for another extension or a write error.
void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress = {}, int supersample = 1);

}  // namespace impasto::render
