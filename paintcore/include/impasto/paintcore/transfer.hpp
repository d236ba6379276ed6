#pragma once
// Brush <-> canvas paint transfer by film splitting, per pair of touching cells.
//
// Where a brush cell holding a_b (mm of paint) touches a canvas cell whose penetrated paint is
// a_c, the two films join and, as the surfaces part, split: at equilibrium the canvas keeps
// deposit_share of a_b + a_c. The split is reached by first-order relaxation in the distance
// travelled and the time pressed, so that the paint moved over a stroke does not depend on
// how many steps the stroke is cut into (docs/simulation.md, "Transfer").
#include <algorithm>
#include <cmath>

#include "impasto/paintcore/simulation_params.hpp"

namespace impasto::paintcore {

// The share of the way to the split covered after moving distance_mm in seconds:
// 1 - exp(-(d / transfer_length + t / transfer_time)). Steps compose: two steps relax as one
// of their summed distance and time.
inline double transfer_relaxation(double distance_mm, double seconds,
                                  const SimulationParams& params) {
  return -std::expm1(-(distance_mm / params.transfer_length_mm + seconds / params.transfer_time_s));
}

// How much more paint than its even share the canvas keeps in a cell whose ground lies
// valley_mm below the brush's footing (< 0 on a crown above it), where the split leaves a film
// of film_mm: paint pressed into a valley of the weave or of dry paint stays there. A film
// much thicker than the valley is deep fills it level, so that its top follows the brush, not
// the ground; a thinner one (a scumble, dry-brush) can fill it only by about its own
// thickness, so the weave reads through: v * film / (film + |v|), by ground_fill.
template <typename T>
T valley_fill(T valley_mm, T film_mm, T ground_fill) {
  const T depth = valley_mm < T(0) ? -valley_mm : valley_mm;
  const T film = film_mm > T(0) ? film_mm : T(0);
  const T sum = film + depth;
  return sum > T(0) ? ground_fill * valley_mm * film / sum : T(0);
}

// The signed paint height moved from brush to canvas (> 0 deposits, < 0 picks up) for
// canvas paint a_c, brush paint a_b and a relaxation `relax` in [0, 1]. `fill` (mm,
// valley_fill) raises the canvas's part where its ground lies below the brush's footing and
// lowers it on the crowns, so thick paint buries the texture under it. A deposit never exceeds
// deposit_share * a_b, a pick-up never (1 - deposit_share) * a_c.
template <typename T>
T brush_transfer_amount(T a_c, T a_b, T relax, T deposit_share, T fill = T(0)) {
  const T amount = (deposit_share * (a_b + a_c) + fill - a_c) * relax;
  // (std::clamp's rule on values, not references: callers' loops vectorise.)
  const T least = -(T(1) - deposit_share) * a_c, most = deposit_share * a_b;
  return amount < least ? least : (most < amount ? most : amount);
}

}  // namespace impasto::paintcore
