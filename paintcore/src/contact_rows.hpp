#pragma once
// The row kernels of the brush's contact with the canvas: where the head presses, and the
// film split between brush and canvas. Free functions over one row with restrict-qualified
// arrays and no branches, so that they vectorise (with gathers where the CPU has them: see
// simd_clones.hpp). Stepper calls them; they hold no state.
#include <cstdint>

namespace impasto::paintcore {

// The head's grids, padded by one cell of nothing on every side, and how it sits on a row.
struct HeadRow {
  const float* coverage;         // padded, (cells + 2)^2
  const float* footprint;        // the underside's height above the tip, mm, padded
  const float* paint;            // the brush's paint height per (unpadded) cell, mm
  int cells = 0;                 // across the unpadded grid
  float u0 = 0, v0 = 0;          // padded brush coordinates of the row's first cell centre
  float step_u = 0, step_v = 0;  // and their change per canvas cell
  float tip_mm = 0;              // height of the brush tip
  // Paint in the ground's valleys below the footing (the mean ground and dry paint around
  // the brush's centre), by ground_fill of their depth, stays put: the drag moves the rest.
  float footing_mm = 0, ground_fill = 0;
  // 1 / the contact depth (penetration plus the paint under the bristles) at which the films
  // join fully: the split fades in over it from the contact's edge (huge: no fade); the drag
  // fades in over as much above the paint surface around the brush's centre (surface_mm).
  float inv_touch_mm = 1e30f;
  float surface_mm = 0;
  // The two grids column-major, for the aligned kernel's quarter turn.
  const float* coverage_transposed = nullptr;
  const float* footprint_transposed = nullptr;
};

// Writes, per canvas cell x in [begin, end) of the row: how deep the head presses (pen), the
// brush cell it touches or -1 (cell), how fully its drag moves the paint (weight), the paint on
// that brush cell (on_brush, 0 where none touches) and how fully the films join (touch, 0..1,
// fading to 0 at the contact's edge). The arrays start at the row's first cell. Returns how
// many cells touch.
int penetrate_row(int begin, int end, const HeadRow& head, const float* __restrict ground,
                  const float* __restrict wet, float* __restrict pen, std::int32_t* __restrict cell,
                  float* __restrict weight, float* __restrict on_brush, float* __restrict touch);

// The cells [begin, end) of a row that the head does not reach: no contact.
void clear_contact(int begin, int end, float* pen, std::int32_t* cell, float* weight,
                   float* on_brush, float* touch);

// The canvas cells of a row, [begin, end) within [0, width), outside which the head's grid
// cannot reach (with a cell to spare): where u0 + x step_u and v0 + x step_v both lie in
// [0, limit).
void head_span(int width, const HeadRow& head, int& begin, int& end);

// The same for a head square to the canvas rows (step_v == 0, or step_u == 0 with along_v:
// turned a quarter): the row then crosses the head along one grid axis at a fixed position on
// the other, so the two grid lines it lies between are blended once and each cell
// interpolates along the row only (6 gathers a cell instead of 10). Agrees with
// penetrate_row to float rounding.
int penetrate_aligned_row(int width, const HeadRow& head, bool along_v,
                          const float* __restrict ground, const float* __restrict wet,
                          float* __restrict pen, std::int32_t* __restrict cell,
                          float* __restrict weight, float* __restrict on_brush,
                          float* __restrict touch);

struct FilmSplit {
  float tip_film_mm = 0;    // most paint a brush cell's tips present to the canvas
  float relax = 0;          // how far this step goes toward the split (transfer.hpp)
  float deposit_share = 0;  // the canvas's share of the joint film
  float ground_fill = 0;    // how much of a valley below the footing the paint fills
  float footing_mm = 0;     // the ground and dry paint around the brush's centre
};

// The paint each touching cell exchanges with its brush cell (xfer, > 0 onto the canvas) and
// that as a share of its source's paint (ratio); new_wet gains it. touch (penetrate_row) scales
// each cell's relaxation. share_cap bounds the brush paint a cell may count on where several
// share its brush cell (on_brush itself where sharing cannot bind: see Stepper::step).
void transfer_row(int width, const FilmSplit& split, const std::int32_t* __restrict cell,
                  const float* __restrict on_brush, const float* __restrict share_cap,
                  const float* __restrict touch, const float* __restrict pen,
                  const float* __restrict ground, const float* __restrict wet,
                  float* __restrict new_wet, float* __restrict xfer, float* __restrict ratio);

// One pigment's share of the exchange: from the brush cell (brush_pigment is that pigment's
// grid on the brush) where paint went onto the canvas, from the canvas where it came off;
// canvas_amount gains it and moved records it.
void transfer_pigment_row(int width, const std::int32_t* __restrict cell,
                          const float* __restrict xfer, const float* __restrict ratio,
                          const float* __restrict brush_pigment, float* __restrict canvas_amount,
                          float* __restrict moved);

}  // namespace impasto::paintcore
