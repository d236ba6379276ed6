#pragma once
// The constants of the paint model, in physical units (mm, mm/s, seconds) so that what a
// stroke leaves depends neither on how densely the pen is sampled nor on the canvas
// resolution. Paint heights are in mm. docs/simulation.md derives each rule.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace impasto::paintcore {

// The cell (mm, 254 dpi) on which the explicit flows' limits a pass were set: the squeeze and
// the levelling make more passes on finer grids, so that what they move per mm is the same
// on every grid (stepper.cpp, levelling.cpp).
inline constexpr double kReferenceCellMm = 0.1;

struct SimulationParams {
  // Transfer: where brush and canvas paint touch, the joint film splits between the two
  // surfaces. The canvas's part relaxes toward deposit_share of the joint film by
  // 1 - exp(-(d / transfer_length_mm + t / transfer_time_s)) over a distance d travelled
  // and a time t pressed.
  double deposit_share = 0.25;      // canvas share of the joint film at equilibrium
  double transfer_length_mm = 0.5;  // distance over which the split is reached (1/e)
  double transfer_time_s = 0.25;
  // Where the brush lifts, the film between bristles and canvas breaks in its middle: the
  // canvas keeps this share of it (a pile where a stroke ends).
  double lift_share = 0.5;
  // The bristle tips present at most this film (mm) of the brush's paint to the split; the
  // rest is held in the bundle and flows down as the tips give theirs away.
  double tip_film_mm = 2.5;
  // Paint pressed into the ground's valleys (the weave, dry paint) below the brush's footing
  // stays there: the canvas's part of the film is raised by this share of the valley's depth.
  double ground_fill = 1.0;           // time over which a still brush reaches it (1/e)
  double brush_flow_length_mm = 4.0;  // paint in the bristles evens out over this distance
  // Squeeze: paint flows down the slope of the brush's penetration (mm/mm) by
  // plough (mm per mm travelled) plus squeeze_mm_s (mm per second pressed).
  double plough = 0.1;
  // The paint the brush touches moves with drag times the brush's velocity (IMPaSTo: 1/2, a
  // sheared film). Less keeps the canvas weave from printing through thick paint, as contact
  // under a spent brush follows the weave's peaks.
  double drag = 0.2;
  double squeeze_mm_s = 1.5;
  // Adhesion: advection never leaves less than this film (mm) in a cell it takes from.
  double min_film_mm = 0.002;
  // The brush rests on the ground, the dry paint and this share of the wet paint (0: it
  // sinks through wet paint to the canvas, 1: it rides on top).
  double wet_support = 0.5;
  // Levelling of the wet paint a stroke leaves: it flows for settle_time_s after the stroke
  // until its slopes are held by the paint body's yield stress (paint_body.hpp).
  double settle_time_s = 2.0;
  // Long steps, an approximation measured in docs/simulation.md ("Long steps"): a brush at
  // least long_step_from_cells across moves up to long_step_share of its width a step
  // instead of one cell (a 128-cell brush: 8 cells, an eighth of the steps); narrower brushes,
  // or a share of 0, keep the one-cell steps bit for bit. A long step's drag is advected in
  // sub-steps of at most long_step_drag_cells of the brush's travel, each with the contact
  // where the brush then was.
  double long_step_share = 0.0625;
  double long_step_from_cells = 64.0;
  double long_step_drag_cells = 1.0;
  // Contact fades in from its edge over this depth (mm): the films of brush and canvas join
  // fully where the contact (the head's penetration plus the paint under its bristles) is this
  // deep, and the bristles drag the paint fully where they are this deep in it (0: at once).
  double touch_mm = 0.3;
};

// Throws std::runtime_error naming the field when a parameter is out of its row's range (below)
// or not finite.
void validate(const SimulationParams& params);

// Every parameter, one row each: its name, its field, the painting file version that first
// holds it, its range and unit, and what it means; in the painting file's order
// (docs/painting-format.md): the one list of them, which validation, `impasto help params` and
// docs/simulation.md's table read (the default is SimulationParams'). A parameter added later
// goes at the end with the file version that adds it; files older than that version load with
// its default.
struct NamedParam {
  const char* name;
  double SimulationParams::*field;
  std::uint32_t file_version;
  double lowest, highest;        // the range, both ends included...
  bool lowest_excluded = false;  // ...unless this says the value must be above `lowest`
  const char* unit = "";         // "mm", "s", "mm/s", "cells", "" (a share or a factor)
  const char* meaning = "";
  // Why `value` is outside the range ("must be in [0, 1], got 2"), or "" when inside.
  std::string out_of_range(double value) const;
};
std::span<const NamedParam> all_simulation_params();
// The parameters a painting file of `file_version` holds, in its order: a prefix of the list
// (versions 1 and 2 held IMPaSTo's per-step constants instead, and hold none of these).
std::span<const NamedParam> simulation_param_fields(std::uint32_t file_version);
// The parameter of that name, or nullptr.
const NamedParam* find_simulation_param(std::string_view name);

// The longest move of one simulation step for a bristled head `brush_cells` across, in cells:
// 1, or for a head at least long_step_from_cells across, long_step_share of its width (if that
// is more). (A blade steps a cell at a time.)
double max_step_cells(const SimulationParams& params, int brush_cells);

// The parameters by name, for command lines and settings files: sets `name` from "NAME=VALUE"
// text; throws naming the field (and listing the known names) when it can't. Does not validate.
void set_param(SimulationParams& params, const std::string& assignment);

}  // namespace impasto::paintcore
