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

// Renders and writes by extension: .png (8-bit, settings.display, sRGB by default) or .exr
// (linear sRGB primaries, full range; settings.display is ignored). Throws
// std::runtime_error naming the file for another extension or a write error.
void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress = {});

}  // namespace impasto::render
