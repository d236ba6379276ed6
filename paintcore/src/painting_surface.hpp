#pragma once
// The painting's side of media and varnish (paint_surface.hpp): the hooks painting.cpp calls
// when paint is loaded, laid by a stroke and dried.
#include <optional>
#include <unordered_map>
#include <vector>

#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "stepper.hpp"
#include "undo_history.hpp"

namespace impasto::paintcore {

// The brush held before_mm3 of paint and was given added_mm3 more, with `medium` (or none).
void mix_brush_medium(Brush& brush, double before_mm3, double added_mm3,
                      const std::optional<Medium>& medium);

// What a stroke's brush laid in each cell so far, by tile: per cell the height laid, its
// volume of medium and that times its log RMS (three planes of kTileCells), so the stroke's
// paint carries the medium the brush had where and when it laid it.
using StrokeMedia = std::unordered_map<int, std::vector<float>>;

// After a step (its stroke's undo step recording), for each cell the step exchanged paint
// with the brush at (Stepper::for_each_exchange): paint the brush laid is booked in `laid`
// with the brush's medium; paint the brush picked up brings the cell's medium into the
// brush's, by volume (mix), so a gloss brush dragged through matte paint carries a mix of the
// two onward. (The part of a cell's paint this stroke laid carries what `laid` booked there.)
void exchange_medium(const Canvas& canvas, const UndoHistory& history, Brush& brush,
                     const Stepper& stepper, StrokeMedia& laid);

// After a stroke (its undo step still recording): the paint each cell of `tiles` gained
// carries the medium the brush laid there (`laid`; where the brush laid none, the paint was
// pushed there: the brush's medium now) into the cell's surface; more than a film of it
// (kSurfaceFilmMm) over a varnish buries the varnish there (the cell's varnish is cleared:
// paint is on top). `laid` is emptied for the next stroke.
void lay_stroke_medium(Canvas& canvas, const UndoHistory& history, const PaintMedium& brush,
                       const std::vector<int>& tiles, StrokeMedia& laid);

// dry(fraction)'s share of the varnish: that fraction of what is wet dries (the undo step
// recording).
void dry_varnish(Canvas& canvas, UndoHistory& history, float fraction);

}  // namespace impasto::paintcore
