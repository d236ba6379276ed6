#include "stroke_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impasto::paintcore {

StrokeSegment::StrokeSegment(std::array<double, 2> from, std::array<double, 2> to,
                             const std::array<double, 2>* before)
    : p0_(from), p1_(to) {
  const double cx = to[0] - from[0], cy = to[1] - from[1];
  const double chord = std::hypot(cx, cy);
  m0_ = m1_ = {cx, cy};
  const double tx = before ? to[0] - (*before)[0] : 0.0, ty = before ? to[1] - (*before)[1] : 0.0;
  const double t_length = std::hypot(tx, ty);
  if (chord > 0.0 && t_length > 0.0) {
    m0_ = {tx / t_length * chord, ty / t_length * chord};
    // Mirror m0 about the chord: m1 = 2 (m0 . c^) c^ - m0.
    const double ux = cx / chord, uy = cy / chord;
    const double along = m0_[0] * ux + m0_[1] * uy;
    m1_ = {2.0 * along * ux - m0_[0], 2.0 * along * uy - m0_[1]};
    // A tangent turned back more than a right angle from the chord (a cusp in the samples)
    // would loop: draw the chord instead.
    if (along <= 0.0) m0_ = m1_ = {cx, cy};
  }
  straight_ = m0_ == m1_;
  if (straight_) {
    for (int k = 0; k <= kChords; ++k) lengths_[k] = chord * k / kChords;
    return;
  }
  std::array<double, 2> last = p0_;
  for (int k = 1; k <= kChords; ++k) {
    const auto next = at(static_cast<double>(k) / kChords);
    lengths_[k] = lengths_[k - 1] + std::hypot(next[0] - last[0], next[1] - last[1]);
    last = next;
  }
}

double StrokeSegment::t_at_length_share(double share) const {
  if (straight_ || !(length() > 0.0)) return std::clamp(share, 0.0, 1.0);
  const double arc = std::clamp(share, 0.0, 1.0) * length();
  const auto after = std::upper_bound(lengths_.begin(), lengths_.end(), arc);
  if (after == lengths_.end()) return 1.0;
  const auto k = static_cast<int>(after - lengths_.begin()) - 1;
  const double chord = lengths_[k + 1] - lengths_[k];
  const double within = chord > 0.0 ? (arc - lengths_[k]) / chord : 0.0;
  return (k + within) / kChords;
}

std::array<double, 2> StrokeSegment::at(double t) const {
  const double t2 = t * t, t3 = t2 * t;
  const double h10 = t3 - 2 * t2 + t;
  const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  // p0 + h01 (p1 - p0) + ...: the same curve (h00 + h01 = 1), but a coordinate the segment
  // does not change comes out exactly as it went in. Summed as h00 p0 + h01 p1 it wandered by
  // a rounding error either side, and a stroke along x stepped up and down by it: the drag's
  // direction flipped from step to step.
  return {p0_[0] + h01 * (p1_[0] - p0_[0]) + h10 * m0_[0] + h11 * m1_[0],
          p0_[1] + h01 * (p1_[1] - p0_[1]) + h10 * m0_[1] + h11 * m1_[1]};
}

double heading_for_travel(double travel_rad) {
  return travel_rad - 0.5 * std::numbers::pi;
}

double follow_heading(double heading_rad, double travel_rad, double distance,
                      double follow_length) {
  const double turn =
      std::remainder(heading_for_travel(travel_rad) - heading_rad, std::numbers::pi);
  return heading_rad + turn * -std::expm1(-distance / follow_length);
}

}  // namespace impasto::paintcore
