#pragma once
// A small picture of a painting for file managers (the freedesktop thumbnailer calls
// `impasto thumbnail %i %o %s`).
#include <filesystem>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/image.hpp"

namespace impasto::app {

// The image scaled down so that its longer side is at most max_side pixels (never up),
// each output pixel the mean of the input pixels it covers (a box filter on the encoded
// values: close enough for a thumbnail). max_side must be positive.
render::Image shrink_to_fit(const render::Image& image, int max_side);

// How many times coarser than its canvas a painting is rendered for a thumbnail of `size`:
// about two cells a pixel, and never below 1 dpi.
int thumbnail_coarsening(const paintcore::CanvasSpec& spec, int size);

// Renders the painting under the default light and writes a PNG of at most size x size.
// Throws std::runtime_error naming the file for an unreadable painting or an unwritable PNG.
void write_thumbnail(const std::filesystem::path& painting, const std::filesystem::path& png,
                     int size);

}  // namespace impasto::app
