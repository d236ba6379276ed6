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
  if (!before || chord == 0.0) return;
  const double tx = to[0] - (*before)[0], ty = to[1] - (*before)[1];
  const double t_length = std::hypot(tx, ty);
  if (t_length == 0.0) return;
  m0_ = {tx / t_length * chord, ty / t_length * chord};
  // Mirror m0 about the chord: m1 = 2 (m0 . c^) c^ - m0.
  const double ux = cx / chord, uy = cy / chord;
  const double along = m0_[0] * ux + m0_[1] * uy;
  m1_ = {2.0 * along * ux - m0_[0], 2.0 * along * uy - m0_[1]};
  // A tangent turned back more than a right angle from the chord (a cusp in the samples)
  // would loop: draw the chord instead.
  if (along <= 0.0) m0_ = m1_ = {cx, cy};
  straight_ = m0_ == m1_;
}

std::array<double, 2> StrokeSegment::at(double t) const {
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
  const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  return {h00 * p0_[0] + h10 * m0_[0] + h01 * p1_[0] + h11 * m1_[0],
          h00 * p0_[1] + h10 * m0_[1] + h01 * p1_[1] + h11 * m1_[1]};
}

double StrokeSegment::max_speed() const {
  constexpr int kChords = 32;
  if (straight_) return std::hypot(p1_[0] - p0_[0], p1_[1] - p0_[1]);
  double fastest = 0.0;
  std::array<double, 2> last = p0_;
  for (int k = 1; k <= kChords; ++k) {
    const auto next = at(static_cast<double>(k) / kChords);
    fastest = std::max(fastest, std::hypot(next[0] - last[0], next[1] - last[1]) * kChords);
    last = next;
  }
  return 1.02 * fastest;
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
