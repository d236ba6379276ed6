#pragma once
// A pigment's curves as `impasto pigments show` tabulates them, `impasto pigments plot` draws
// them and the window's pigment editor plots them: at its K's wavelengths, K, S, K/S
// (infinite where S = 0) and R∞ of an opaque layer (zero where K = S = 0).
#include <impasto/data/kubelka_munk.hpp>
#include <impasto/data/pigments.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace impasto::app {

struct PigmentCurves {
  std::vector<double> nm, k, s, k_over_s, r_infinite;
};

inline PigmentCurves pigment_curves(const data::Pigment& pigment) {
  PigmentCurves c{pigment.K.wavelengths_nm, pigment.K.values, {}, {}, {}};
  for (std::size_t i = 0; i < c.nm.size(); ++i) {
    const double k = c.k[i], s = pigment.S.at(c.nm[i]);
    c.s.push_back(s);
    c.k_over_s.push_back(s > 0 ? k / s : HUGE_VAL);
    c.r_infinite.push_back(data::reflectance_infinite(k, s));
  }
  return c;
}

}  // namespace impasto::app
