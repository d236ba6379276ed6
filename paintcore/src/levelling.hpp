#pragma once
// Levelling: after a stroke its wet paint flows down its own surface until the slopes are
// held by the paint's yield stress (Bingham film flow; docs/simulation.md, "Paint body").
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::paintcore {

struct LevellingReport {
  int iterations = 0;
  double moved_mm3 = 0;  // paint volume that crossed a cell face, in all
};

// Lets the wet paint of `tiles` (tile indices, each existing) flow for params.settle_time_s.
// Paint crosses only faces between cells of these tiles. Deterministic (Jacobi updates in a
// fixed order); conserves volume and each pigment face by face.
LevellingReport settle_wet_paint(Canvas& canvas, const std::vector<int>& tiles, int slot_count,
                                 PaintBody body, const SimulationParams& params);

// The height (mm of paint) that crosses one face in `seconds`, from a cell holding h mm of wet
// paint whose surface stands `drop` mm above its neighbour's, `cell_mm` apart: Bingham film
// flux rho g S (h - h_y)^2 (2h + h_y) / (6 mu), h_y = tau_y / (rho g S), none where the
// yield stress holds the slope. Capped to an eighth of the drop the yield slope does not hold
// (and a quarter of the paint), so that four faces together never overshoot.
double levelling_flow_mm(double h, double drop, double cell_mm, double seconds,
                         const PaintBodyInfo& body);

}  // namespace impasto::paintcore
