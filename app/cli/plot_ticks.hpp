#pragma once
// Axis ticks at round numbers (1, 2, 5 × 10^n), shared by the figures the command line writes
// (pigment_figure.*) and the window's plots (window/plot.*).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace impasto::app {

// About `wanted` ticks covering [lo, hi].
inline std::vector<double> nice_ticks(double lo, double hi, int wanted = 5) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(wanted, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  // Counted, not summed: a step below the values' resolution cannot loop forever.
  const double first = std::ceil(lo / step);
  for (int i = 0; i < 100; ++i) {
    const double t = (first + i) * step;
    if (t > hi + step * 1e-9) break;
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  }
  return ticks;
}

inline std::string tick_label(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace impasto::app
