#pragma once
// Brush <-> canvas paint transfer: Algorithm 1 of IMPaSTo, per pair of touching cells.
#include <algorithm>
#include <cmath>

#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::paintcore {

template <typename T>
T smoothstep(T edge0, T edge1, T x) {
  const T t = std::clamp((x - edge0) / (edge1 - edge0), T(0), T(1));
  return t * t * (T(3) - T(2) * t);
}

// Constants of Algorithm 1 in the precision of the inner loop.
template <typename T>
struct TransferConstants {
  T xfer_fraction, inv_equal_paint_cutoff, max_xfer, velocity_low, velocity_high;
  explicit TransferConstants(const SimulationParams& p)
      : xfer_fraction(static_cast<T>(p.xfer_fraction)),
        inv_equal_paint_cutoff(static_cast<T>(1.0 / p.equal_paint_cutoff_mm)),
        max_xfer(static_cast<T>(p.max_xfer_mm)),
        velocity_low(static_cast<T>(p.velocity_cutoff_low)),
        velocity_high(static_cast<T>(p.velocity_cutoff_high)) {}
};

// Algorithm 1. a_c: paint height of the canvas cell that the brush penetrates (volume times
// the penetrated fraction); a_b: paint height on the touching brush cell; speed: the brush's
// tangential speed in cells/step. Returns the signed amount (mm of paint height) moved from
// brush to canvas: > 0 deposits, < 0 picks up, 0 moves nothing.
template <typename T>
T brush_transfer_amount(T a_c, T a_b, T speed, const TransferConstants<T>& k) {
  const T paint_diff = a_b - a_c;
  const T equal_paint_cutoff = std::min(std::abs(paint_diff) * k.inv_equal_paint_cutoff, T(1));
  const T velocity_cutoff = smoothstep(k.velocity_low, k.velocity_high, speed);
  const T source = paint_diff > T(0) ? a_b : a_c;
  const T amount =
      std::clamp(source * k.xfer_fraction * equal_paint_cutoff * velocity_cutoff, T(0), k.max_xfer);
  return paint_diff > T(0) ? amount : -amount;
}

struct TransferAmounts {
  double brush_to_canvas = 0;  // x_bc
  double canvas_to_brush = 0;  // x_cb
};

// Algorithm 1 as in the paper, returning (x_bc, x_cb).
inline TransferAmounts compute_brush_transfer_amount(double a_c, double a_b, double speed,
                                                     const SimulationParams& params) {
  const double signed_amount =
      brush_transfer_amount(a_c, a_b, speed, TransferConstants<double>(params));
  return signed_amount > 0 ? TransferAmounts{signed_amount, 0.0}
                           : TransferAmounts{0.0, -signed_amount};
}

}  // namespace impasto::paintcore
