#include <cmath>

#include "impasto/flakes/counter_rng.hpp"

namespace impasto::flakes {

namespace {
// Inversion by sequential search: exact, about mean + 1 steps.
int poisson_inversion(CounterRng& rng, double mean) {
  double p = std::exp(-mean);
  double cdf = p;
  const double u = rng.uniform();
  int k = 0;
  while (u > cdf && k < 1000) {  // the bound only guards rounding in the tail
    ++k;
    p *= mean / k;
    cdf += p;
  }
  return k;
}

// W. Hörmann, "The transformed rejection method for generating Poisson random variables",
// Insurance: Mathematics and Economics 12 (1993) 39–45 (algorithm PTRS), for mean ≥ 10.
int poisson_ptrs(CounterRng& rng, double mean) {
  const double slam = std::sqrt(mean);
  const double loglam = std::log(mean);
  const double b = 0.931 + 2.53 * slam;
  const double a = -0.059 + 0.02483 * b;
  const double inv_alpha = 1.1239 + 1.1328 / (b - 3.4);
  const double vr = 0.9277 - 3.6224 / (b - 2.0);
  for (;;) {
    const double u = rng.uniform() - 0.5;
    const double v = rng.uniform();
    const double us = 0.5 - std::fabs(u);
    const double k = std::floor((2.0 * a / us + b) * u + mean + 0.43);
    if (us >= 0.07 && v <= vr) return static_cast<int>(k);
    if (k < 0.0 || (us < 0.013 && v > us)) continue;
    if (std::log(v) + std::log(inv_alpha) - std::log(a / (us * us) + b) <=
        -mean + k * loglam - std::lgamma(k + 1.0)) {
      return static_cast<int>(k);
    }
  }
}
}  // namespace

int sample_sparkle_count(CounterRng& rng, double mean) {
  if (!(mean > 0.0)) return 0;
  if (mean < 0.1) return rng.uniform() <= mean ? 1 : 0;
  if (mean < 10.0) return poisson_inversion(rng, mean);
  // Past 1e9 the relative spread is below 3e-5; the count saturates short of INT_MAX.
  if (mean > 1e9) return static_cast<int>(std::lround(std::fmin(mean, 2e9)));
  return poisson_ptrs(rng, mean);
}

}  // namespace impasto::flakes
