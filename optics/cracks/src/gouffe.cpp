#include "impasto/cracks/gouffe.hpp"

#include <cmath>

namespace impasto::cracks {

double gouffe_term(int n, double rho0, const ViewFactors& vf) {
  if (n < 1) return 0.0;
  if (n == 1) return rho0 * vf.F;
  return std::pow(rho0, n) * (1.0 - vf.F) * vf.G * std::pow(1.0 - vf.G, n - 2);
}

double gouffe_partial_sum(int n, double rho0, const ViewFactors& vf) {
  if (n < 1) return 0.0;
  // Sum by recurrence: each further term is the previous one times rho0 (1 - G).
  double sum = rho0 * vf.F;
  double term = rho0 * rho0 * (1.0 - vf.F) * vf.G;
  for (int k = 2; k <= n; ++k) {
    sum += term;
    term *= rho0 * (1.0 - vf.G);
  }
  return sum;
}

}  // namespace impasto::cracks
