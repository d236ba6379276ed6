#pragma once
// The painting's side of media and varnish (paint_surface.hpp): the hooks painting.cpp calls
// when paint is loaded, laid by a stroke and dried.
#include <optional>
#include <vector>

#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "stepper.hpp"
#include "undo_history.hpp"

namespace impasto::paintcore {

// The brush held before_mm3 of paint and was given added_mm3 more, with `medium` (or none).
void mix_brush_medium(Brush& brush, double before_mm3, double added_mm3,
                      const std::optional<Medium>& medium);

// After a step (its stroke's undo step recording): the paint the brush picked up from each
// cell (Stepper::for_each_pick_up) brings that cell's medium into the brush's, by volume
// (mix), so a gloss brush dragged through matte paint carries a mix of the two onward. The
// part of a cell's paint laid by this stroke carries the brush's medium (the surface takes it
// only when the stroke ends: lay_stroke_medium).
void pick_up_medium(const Canvas& canvas, const UndoHistory& history, Brush& brush,
                    const Stepper& stepper);

// After a stroke (its undo step still recording): the paint each cell of `tiles` gained
// carries the brush's medium into the cell's surface; more than a film of it (kSurfaceFilmMm)
// over a varnish buries the varnish there (the cell's varnish is cleared: paint is on top).
void lay_stroke_medium(Canvas& canvas, const UndoHistory& history, const PaintMedium& brush,
                       const std::vector<int>& tiles);

// dry(fraction)'s share of the varnish: that fraction of what is wet dries (the undo step
// recording).
void dry_varnish(Canvas& canvas, UndoHistory& history, float fraction);

}  // namespace impasto::paintcore
