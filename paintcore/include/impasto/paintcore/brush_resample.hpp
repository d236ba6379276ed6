#pragma once
// Moving a brush's paint onto a brush of another head or size, so that changing brushes
// keeps the paint instead of wiping it.
#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {

// Puts the paint of `from` onto `to` (whose paint grid is overwritten), in brush space: both
// grids span the head's square u, v in [-1, 1], so each cell of `from` goes to the cells of
// `to` it overlaps, by overlap area. Paint that lands on a cell `to` does not cover moves to
// the nearest cell it covers. Every total (volume, each pigment) is kept: the sums of
// `to`'s float cells are corrected toward `from`'s, and what float rounding still leaves
// over is returned (from's totals minus to's, in mm^3 for cells of `cell_area_mm2`, summed
// like Painting::brush_totals) for the ledger. `to` gets at least `from`'s pigment slots and
// the paint's body.
PaintTotals resample_brush_paint(const Brush& from, Brush& to, double cell_area_mm2);

}  // namespace impasto::paintcore
