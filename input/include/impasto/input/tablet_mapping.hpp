#pragma once
// Pure functions from tablet space to the painting: which part of the tablet maps onto which
// target rectangle (the screen, a window, or a chosen area), and the pressure curve.
#include <impasto/paintcore/pen_sample.hpp>

namespace impasto::input {

// An axis-aligned rectangle: origin at its top-left corner, +y downwards.
struct Rect {
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;
  bool operator==(const Rect&) const = default;
};

struct Point {
  double x = 0.0;
  double y = 0.0;
};

// Maps a rectangle of the tablet (mm) onto a target rectangle (any unit: screen pixels,
// canvas mm). With keep_aspect the tablet area used is the largest one centred in the
// given area with the target's aspect ratio, so circles stay circles.
class AreaMapping {
 public:
  AreaMapping(Rect tablet_mm, Rect target, bool keep_aspect);

  // The part of the tablet that is used.
  Rect used_tablet_area() const { return used_; }
  // A tablet position in target units; positions outside the used area land on its edge.
  Point map(double x_mm, double y_mm) const;
  // The sample with its position mapped (everything else unchanged).
  paintcore::PenSample map(const paintcore::PenSample& sample) const;

 private:
  Rect used_;
  Rect target_;
};

// The largest rectangle centred in `area` with the aspect ratio width/height of `shape`.
Rect fit_aspect(Rect area, Rect shape);

// How pen pressure (0..1) becomes the pressure the brush feels (0..1).
class PressureCurve {
 public:
  // p -> p^gamma; gamma > 1 softens, < 1 hardens. Identity by default.
  static PressureCurve gamma(double exponent);
  // A cubic Bezier from (0,0) to (1,1) with control points (x1,y1), (x2,y2); x1 and x2 in
  // 0..1 so that the curve is a function of pressure (as in tablet drivers' settings).
  static PressureCurve bezier(double x1, double y1, double x2, double y2);

  PressureCurve() = default;
  double apply(double pressure) const;

 private:
  enum class Kind { kGamma, kBezier };
  Kind kind_ = Kind::kGamma;
  double gamma_ = 1.0;
  double x1_ = 0.0, y1_ = 0.0, x2_ = 1.0, y2_ = 1.0;
};

}  // namespace impasto::input
