#pragma once
// The procedural canvas weave: the base height of the canvas surface, a plain weave of
// threads whose thickness varies from thread to thread. Computed from the position alone,
// so untouched tiles need no storage and any DPI sees the same cloth.
#include <cstdint>

namespace impasto::paintcore {

inline constexpr double kWeaveThreadPitchMm = 0.6;  // distance between neighbouring threads
inline constexpr double kWeaveAmplitudeMm = 0.05;   // height of a thread crossing over

// Height in mm of the canvas surface at (x_mm, y_mm); seed 0 gives a flat canvas (0).
float canvas_weave_height_mm(std::uint64_t seed, double x_mm, double y_mm);
// The heights of a grid of cells, columns at x_mm[0..nx) and rows at y_mm[0..ny), into
// out[y * stride + x]: the same floats as canvas_weave_height_mm at each cell, with what one
// coordinate decides computed once a column or row (a tile's weave, 5x fewer sines).
void canvas_weave_heights_mm(std::uint64_t seed, const double* x_mm, int nx, const double* y_mm,
                             int ny, float* out, int stride);

}  // namespace impasto::paintcore
