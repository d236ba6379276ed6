#include <impasto/input/tablet_mapping.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::input {

namespace {

void check_rect(const Rect& r, const char* what) {
  const bool finite =
      std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.width) && std::isfinite(r.height);
  if (!finite || !(r.width > 0.0) || !(r.height > 0.0)) {
    throw std::invalid_argument(std::string(what) + " must have a finite, positive size");
  }
}

// x(t) or y(t) of a cubic Bezier from 0 to 1 with control values a and b.
double bezier_coordinate(double t, double a, double b) {
  const double u = 1.0 - t;
  return 3.0 * u * u * t * a + 3.0 * u * t * t * b + t * t * t;
}

}  // namespace

Rect fit_aspect(Rect area, Rect shape) {
  const double aspect = shape.width / shape.height;
  Rect fitted = area;
  if (area.width / area.height > aspect) {
    fitted.width = area.height * aspect;
    fitted.x = area.x + 0.5 * (area.width - fitted.width);
  } else {
    fitted.height = area.width / aspect;
    fitted.y = area.y + 0.5 * (area.height - fitted.height);
  }
  return fitted;
}

AreaMapping::AreaMapping(Rect tablet_mm, Rect target, bool keep_aspect) : target_(target) {
  check_rect(tablet_mm, "the tablet area");
  check_rect(target, "the target area");
  used_ = keep_aspect ? fit_aspect(tablet_mm, target) : tablet_mm;
}

Point AreaMapping::map(double x_mm, double y_mm) const {
  const double u = std::clamp((x_mm - used_.x) / used_.width, 0.0, 1.0);
  const double v = std::clamp((y_mm - used_.y) / used_.height, 0.0, 1.0);
  return {target_.x + u * target_.width, target_.y + v * target_.height};
}

paintcore::PenSample AreaMapping::map(const paintcore::PenSample& sample) const {
  paintcore::PenSample mapped = sample;
  const Point p = map(sample.x_mm, sample.y_mm);
  mapped.x_mm = p.x;
  mapped.y_mm = p.y;
  return mapped;
}

PressureCurve PressureCurve::gamma(double exponent) {
  if (!std::isfinite(exponent) || !(exponent > 0.0)) {
    throw std::invalid_argument("pressure gamma must be a positive number");
  }
  PressureCurve curve;
  curve.gamma_ = exponent;
  return curve;
}

PressureCurve PressureCurve::bezier(double x1, double y1, double x2, double y2) {
  for (double v : {x1, y1, x2, y2}) {
    if (!std::isfinite(v) || v < 0.0 || v > 1.0) {
      throw std::invalid_argument("pressure curve control points must lie in 0..1");
    }
  }
  PressureCurve curve;
  curve.kind_ = Kind::kBezier;
  curve.x1_ = x1;
  curve.y1_ = y1;
  curve.x2_ = x2;
  curve.y2_ = y2;
  return curve;
}

double PressureCurve::apply(double pressure) const {
  const double p = std::isfinite(pressure) ? std::clamp(pressure, 0.0, 1.0) : 0.0;
  if (kind_ == Kind::kGamma) return std::pow(p, gamma_);
  // With x1, x2 in 0..1, x(t) is non-decreasing: bisection finds the t with x(t) = p.
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bezier_coordinate(mid, x1_, x2_) < p ? lo : hi) = mid;
  }
  return std::clamp(bezier_coordinate(0.5 * (lo + hi), y1_, y2_), 0.0, 1.0);
}

}  // namespace impasto::input
