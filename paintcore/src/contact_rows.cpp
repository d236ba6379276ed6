#include "contact_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "impasto/paintcore/brush.hpp"

#include "impasto/paintcore/transfer.hpp"
#include "simd_clones.hpp"

namespace impasto::paintcore {
namespace {

// Keeps a deposit a relative hair below what its brush cell holds (float rounding).
constexpr float kBelowBound = 1.0f - 1e-5f;

// What one canvas cell's contact writes, from the head interpolated there: shared by both
// row kernels. Returns 1 where the brush touches the cell.
[[gnu::always_inline]] inline int write_contact(int x, float coverage, float underside,
                                                bool covered, std::int32_t b, float paint,
                                                float ground, float wet, float tip_mm,
                                                float footing_mm, float ground_fill,
                                                float inv_touch_mm, float surface_mm, float* pen,
                                                std::int32_t* cell, float* weight, float* on_brush,
                                                float* touch) {
  // The head presses where its underside is below the paint surface; the paint hanging
  // under the bristles touches before that (a loaded brush lays a broad mark, a dry one
  // skips).
  const float penetration = ground + wet - (tip_mm + underside);
  const bool touches = covered & (penetration + paint > 0.0f);
  // (Masks by multiplication, of finite values: selects here became branches.)
  const int hit = touches;
  const float mask = static_cast<float>(hit);
  pen[x] = mask * greater(penetration, 0.0f);
  cell[x] = (b + 1) * hit - 1;
  on_brush[x] = mask * paint;
  // Contact fades in from its edge over touch_mm: the films join (the split relaxes) by the
  // depth of the contact, the paint under the bristles included; the bristles drag the paint
  // fully where the underside reaches the paint surface around the brush's centre, less and
  // less to touch_mm above it (the head's shape and depth alone: measured against each cell's
  // own surface, or fading in below the surface, the drag followed the weave and printed it
  // through thick paint). A contact all or nothing left the edge of every step where a
  // lifting or easing brush's contact shrank: rings in each dab.
  touch[x] = mask * lesser((penetration + paint) * inv_touch_mm, 1.0f);
  const float reaches =
      lesser(greater((surface_mm - (tip_mm + underside)) * inv_touch_mm + 1.0f, 0.0f), 1.0f);
  // The head moves the paint in full from half a cell inside its edge, all but what lies in
  // a valley of the ground below its footing: the threads around hold that (the drag used
  // to carry it onto the crowns ahead, printing the weave back through thick paint).
  const float trapped = lesser(ground_fill * greater(footing_mm - ground, 0.0f), wet);
  const float mobile = wet > 0.0f ? (wet - trapped) / wet : 1.0f;
  weight[x] = mask * reaches * mobile * lesser(greater(2.0f * coverage - 1.0f, 0.0f), 1.0f);
  return hit;
}

}  // namespace

IMPASTO_SIMD_CLONES int penetrate_row(int begin, int end, const HeadRow& head,
                                      const float* __restrict ground, const float* __restrict wet,
                                      float* __restrict pen, std::int32_t* __restrict cell,
                                      float* __restrict weight, float* __restrict on_brush,
                                      float* __restrict touch) {
  const float* coverage_grid = head.coverage;
  const float* footprint_grid = head.footprint;
  const float* brush_paint = head.paint;
  const int n = head.cells, padded = n + 2;
  const auto limit = static_cast<float>(n) + 1.0f;
  const float u0 = head.u0, v0 = head.v0, step_u = head.step_u, step_v = head.step_v;
  const float tip_mm = head.tip_mm;
  const float footing_mm = head.footing_mm, ground_fill = head.ground_fill;
  const float inv_touch_mm = head.inv_touch_mm, surface_mm = head.surface_mm;
  int contacts = 0;
  for (int x = begin; x < end; ++x) {
    // The head between brush cell centres: coverage and underside interpolated bilinearly,
    // so that a sharp edge (a flat, a knife) moves smoothly across the canvas cells rather
    // than jumping a cell at a time (which printed a step pattern). On the padded grid the
    // four cells around (u, v) always exist; cells off the head read its corner, masked.
    const float u_raw = u0 + static_cast<float>(x) * step_u;
    const float v_raw = v0 + static_cast<float>(x) * step_v;
    const bool inside = (u_raw >= 0.0f) & (v_raw >= 0.0f) & (u_raw < limit) & (v_raw < limit);
    const float u = inside ? u_raw : 0.0f, v = inside ? v_raw : 0.0f;
    const int i0 = static_cast<int>(u), j0 = static_cast<int>(v);
    const float fx = u - static_cast<float>(i0), fy = v - static_cast<float>(j0);
    const int p = j0 * padded + i0;
    const float w00 = (1.0f - fx) * (1.0f - fy), w10 = fx * (1.0f - fy);
    const float w01 = (1.0f - fx) * fy, w11 = fx * fy;
    const float coverage = w00 * coverage_grid[p] + w10 * coverage_grid[p + 1] +
                           w01 * coverage_grid[p + padded] + w11 * coverage_grid[p + padded + 1];
    const float underside = w00 * footprint_grid[p] + w10 * footprint_grid[p + 1] +
                            w01 * footprint_grid[p + padded] + w11 * footprint_grid[p + padded + 1];
    // The nearest brush cell (its padded index: the padding covers nothing) holds the paint
    // this canvas cell exchanges. (u + 0.5 >= 0.5: the cast truncates as floor would.)
    const int i_near = static_cast<int>(u + 0.5f), j_near = static_cast<int>(v + 0.5f);
    const bool covered = inside & (coverage_grid[j_near * padded + i_near] > 0.0f);
    const std::int32_t b = covered ? (j_near - 1) * n + (i_near - 1) : 0;
    contacts += write_contact(x, coverage, underside, covered, b, brush_paint[b], ground[x], wet[x],
                              tip_mm, footing_mm, ground_fill, inv_touch_mm, surface_mm, pen, cell,
                              weight, on_brush, touch);
  }
  return contacts;
}

void clear_contact(int begin, int end, float* pen, std::int32_t* cell, float* weight,
                   float* on_brush, float* touch) {
  if (end <= begin) return;
  std::fill(touch + begin, touch + end, 0.0f);
  std::fill(pen + begin, pen + end, 0.0f);
  std::fill(cell + begin, cell + end, -1);
  std::fill(weight + begin, weight + end, 0.0f);
  std::fill(on_brush + begin, on_brush + end, 0.0f);
}

void head_span(int width, const HeadRow& head, int& begin, int& end) {
  // Each coordinate a + x d stays in [0, limit) on an interval of x; the head is where both do.
  double lo = 0.0, hi = width;
  const double limit = head.cells + 1.0;
  for (const auto& [a, d] : {std::pair<double, double>{head.u0, head.step_u},
                             std::pair<double, double>{head.v0, head.step_v}}) {
    if (d == 0.0) {
      if (!(a >= 0.0 && a < limit)) hi = lo;  // the row misses the head
      continue;
    }
    const double x_at_0 = -a / d, x_at_limit = (limit - a) / d;
    lo = std::max(lo, std::min(x_at_0, x_at_limit));
    hi = std::min(hi, std::max(x_at_0, x_at_limit));
  }
  // A cell to spare on each side: the kernel's own test decides at the edges.
  begin = static_cast<int>(std::clamp(std::floor(lo) - 1.0, 0.0, static_cast<double>(width)));
  end = static_cast<int>(std::clamp(std::ceil(hi) + 1.0, 0.0, static_cast<double>(width)));
  if (hi <= lo) begin = end = 0;
}

IMPASTO_SIMD_CLONES int penetrate_aligned_row(int width, const HeadRow& head, bool along_v,
                                              const float* __restrict ground,
                                              const float* __restrict wet, float* __restrict pen,
                                              std::int32_t* __restrict cell,
                                              float* __restrict weight, float* __restrict on_brush,
                                              float* __restrict touch) {
  const int n = head.cells, padded = n + 2;
  const auto limit = static_cast<float>(n) + 1.0f;
  // The row walks the head along t (u, or v for a head turned a quarter) at a fixed s.
  const float t0 = along_v ? head.v0 : head.u0, step_t = along_v ? head.step_v : head.step_u;
  const float s = along_v ? head.u0 : head.v0;
  const float tip_mm = head.tip_mm;
  const float footing_mm = head.footing_mm, ground_fill = head.ground_fill;
  const float inv_touch_mm = head.inv_touch_mm, surface_mm = head.surface_mm;
  if (!(s >= 0.0f && s < limit)) {  // the row passes beside the head
    std::fill_n(pen, width, 0.0f);
    std::fill_n(cell, width, -1);
    std::fill_n(weight, width, 0.0f);
    std::fill_n(on_brush, width, 0.0f);
    std::fill_n(touch, width, 0.0f);
    return 0;
  }
  // The two brush lines s lies between, blended once for the whole canvas row, and the
  // nearest line (the padding's lines cover nothing).
  const int s0 = static_cast<int>(s), s_near = static_cast<int>(s + 0.5f);
  const float fs = s - static_cast<float>(s0);
  // Line s of the grids as the row walks them: a row of the grids, or of their transposes.
  const float* coverage = along_v ? head.coverage_transposed : head.coverage;
  const float* footprint = along_v ? head.footprint_transposed : head.footprint;
  const float* coverage_below = coverage + static_cast<std::ptrdiff_t>(s0) * padded;
  const float* footprint_below = footprint + static_cast<std::ptrdiff_t>(s0) * padded;
  float coverage_line[kMaxBrushCells + 2], footprint_line[kMaxBrushCells + 2];
  for (int k = 0; k < padded; ++k) {
    coverage_line[k] = (1.0f - fs) * coverage_below[k] + fs * coverage_below[k + padded];
    footprint_line[k] = (1.0f - fs) * footprint_below[k] + fs * footprint_below[k + padded];
  }
  // The brush cell (unpadded) at padded line position k is first_cell + k * cell_step.
  const std::int32_t cell_step = along_v ? n : 1;
  const std::int32_t first_cell = along_v ? (s_near - 1) - n : (s_near - 1) * n - 1;
  // The nearest line's paint where the head covers it, else -1 (paint is never negative):
  // one read a cell tells both.
  const float* nearest_coverage = coverage + static_cast<std::ptrdiff_t>(s_near) * padded;
  float nearest_paint[kMaxBrushCells + 2];
  for (int k = 0; k < padded; ++k)
    nearest_paint[k] = nearest_coverage[k] > 0.0f ? head.paint[first_cell + k * cell_step] : -1.0f;
  const float* blended_coverage = coverage_line;
  const float* blended_footprint = footprint_line;
  const float* paint_at = nearest_paint;
  int contacts = 0;
  for (int x = 0; x < width; ++x) {
    const float t_raw = t0 + static_cast<float>(x) * step_t;
    const bool inside = (t_raw >= 0.0f) & (t_raw < limit);
    const float t = inside ? t_raw : 0.0f;
    const int k0 = static_cast<int>(t);
    const float ft = t - static_cast<float>(k0);
    const float coverage = (1.0f - ft) * blended_coverage[k0] + ft * blended_coverage[k0 + 1];
    const float underside = (1.0f - ft) * blended_footprint[k0] + ft * blended_footprint[k0 + 1];
    const int k_near = static_cast<int>(t + 0.5f);
    const float paint = paint_at[k_near];
    const bool covered = inside & (paint >= 0.0f);
    const std::int32_t b = covered ? first_cell + k_near * cell_step : 0;
    contacts += write_contact(x, coverage, underside, covered, b, covered ? paint : 0.0f, ground[x],
                              wet[x], tip_mm, footing_mm, ground_fill, inv_touch_mm, surface_mm,
                              pen, cell, weight, on_brush, touch);
  }
  return contacts;
}

IMPASTO_SIMD_CLONES void transfer_row(int width, const FilmSplit& split,
                                      const std::int32_t* __restrict cell,
                                      const float* __restrict on_brush,
                                      const float* __restrict share_cap,
                                      const float* __restrict touch, const float* __restrict pen,
                                      const float* __restrict ground, const float* __restrict wet,
                                      float* __restrict new_wet, float* __restrict xfer,
                                      float* __restrict ratio) {
  const float tip_film_mm = split.tip_film_mm, relax = split.relax;
  const float deposit_share = split.deposit_share, ground_fill = split.ground_fill;
  const float footing_mm = split.footing_mm;
  // Branch-free, as the direction varies from cell to cell.
  for (int x = 0; x < width; ++x) {
    const bool touches = cell[x] >= 0;
    // a_c: the canvas paint the brush reaches, with its head and the paint under it (a
    // fraction of the wet layer's depth).
    const float reach = pen[x] + on_brush[x];
    const bool wet_here = wet[x] > 0.0f;
    const float depth_share = lesser(reach / (wet_here ? wet[x] : 1.0f), 1.0f);
    const float a_c = wet_here ? new_wet[x] * depth_share : 0.0f;
    // a_b: the paint on the brush cell it touches (a height, the same for every canvas cell
    // under that brush cell), as far as the tips present it: the rest waits in the bundle's
    // belly (a loaded brush lays an even stroke until it runs dry, rather than dumping its
    // load at the start). Where k canvas cells share the brush cell, share_cap keeps each
    // deposit to deposit_share * a_b <= on_brush / k, so together they never take more than
    // it holds; dividing the height by k instead printed the sharing pattern into the paint.
    // (A hair below the bound: float rounding must never let the brush cell go negative.)
    const float a_b = kBelowBound * lesser(lesser(on_brush[x], tip_film_mm), share_cap[x]);
    // The film split (transfer.hpp), the ground's valleys filled as deep as the film
    // allows; exactly 0 where nothing touches.
    const float fill =
        valley_fill(footing_mm - ground[x], deposit_share * (a_b + a_c), ground_fill);
    const float amount = brush_transfer_amount(a_c, a_b, relax * touch[x], deposit_share, fill);
    const float moved = touches ? amount : 0.0f;
    // Pigments go in the source's proportions (volume-weighted mixing).
    const float source = moved > 0.0f ? on_brush[x] : new_wet[x];
    ratio[x] = moved / (source > 0.0f ? source : 1.0f);
    xfer[x] = moved;
    new_wet[x] += moved;
  }
}

IMPASTO_SIMD_CLONES void transfer_pigment_row(int width, const std::int32_t* __restrict cell,
                                              const float* __restrict xfer,
                                              const float* __restrict ratio,
                                              const float* __restrict brush_pigment,
                                              float* __restrict canvas_amount,
                                              float* __restrict moved) {
  for (int x = 0; x < width; ++x) {
    // (Read for every cell, cell 0 standing in for none, and used only where paint went
    // onto the canvas: the loop stays free of branches.)
    const float on_brush = brush_pigment[cell[x] < 0 ? 0 : cell[x]];
    const float source = xfer[x] > 0.0f ? on_brush : canvas_amount[x];
    moved[x] = source * ratio[x];  // signed like the paint; 0 where nothing moves
    canvas_amount[x] += moved[x];
  }
}

}  // namespace impasto::paintcore
