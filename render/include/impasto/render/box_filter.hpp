#pragma once
// A zoomed-out view of an image of cells as a box filter makes it: each pixel the average of
// the cells under its footprint, weighted by how much of the footprint each holds.
#include "impasto/render/image.hpp"

namespace impasto::render {

// The width x height view centred on `cells` (one pixel a cell, linear values) at
// `cells_per_pixel` (>= 1): pixel (x, y) covers cells [x0 + x z, x0 + (x + 1) z) across, x0 =
// (cells.width - width z) / 2, and likewise down. Cells beyond the edge repeat the edge's.
// What the window's zoomed-out view computes on the GPU (canvas_km_frag.glsl, footprint_colour)
// and what `impasto bench zoom` compares it with.
Image box_filtered(const Image& cells, double cells_per_pixel, int width, int height);

}  // namespace impasto::render
