#pragma once
// The brush's path between two pen samples: a curve through the samples, not a polygon, and
// the heading of a brush that trails the hand.
#include <array>

#include "impasto/paintcore/brush_pose.hpp"  // follow_heading, heading_for_travel

namespace impasto::paintcore {

// A cubic Hermite segment from `from` to `to` (canvas cells). Its tangent at `from` points
// along to - before (Catmull-Rom's direction, with the chord's length); its tangent at `to`
// mirrors that one about the chord, so samples on a circle give a near-exact arc and the next
// segment starts in the direction this one ends. Without `before` (a stroke's first
// segment) it is the straight chord. Needs no later sample: no added latency.
class StrokeSegment {
 public:
  StrokeSegment(std::array<double, 2> from, std::array<double, 2> to,
                const std::array<double, 2>* before);
  std::array<double, 2> at(double t) const;  // t in [0, 1]
  // Its arc length (cells), and the parameter t at which the arc from `from` is `share` of it:
  // exact on a straight segment, over 32 chords on a curve (the brush steps by distance
  // along the path, not by the curve's parameter, whose speed varies).
  double length() const { return lengths_.back(); }
  double t_at_length_share(double share) const;

 private:
  static constexpr int kChords = 32;
  std::array<double, 2> p0_, p1_, m0_, m1_;
  bool straight_ = true;
  std::array<double, kChords + 1> lengths_{};  // arc length from `from` at t = k / kChords
};

}  // namespace impasto::paintcore
