#include "impasto/data/kubelka_munk.hpp"

#include <cmath>

namespace impasto::data {

double ks_from_reflectance(double reflectance) {
  const double absorbed = 1.0 - reflectance;
  return absorbed * absorbed / (2.0 * reflectance);
}

double reflectance_from_ks(double ks) {
  // 1 + q − sqrt(q² + 2q) written as 1 / (1 + q + sqrt(q² + 2q)) to avoid cancellation for large q.
  return 1.0 / (1.0 + ks + std::sqrt(ks * ks + 2.0 * ks));
}

double Saunderson::to_internal(double measured) const {
  return (measured - k1) / (1.0 - k1 - k2 + k2 * measured);
}

double Saunderson::to_measured(double internal) const {
  return k1 + (1.0 - k1) * (1.0 - k2) * internal / (1.0 - k2 * internal);
}

}  // namespace impasto::data
