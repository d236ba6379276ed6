#pragma once
// What was put on the brush by loads and taken off by wipes, so that at any time
// canvas + brush = loaded - wiped can be checked.
#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {

struct Ledger {
  PaintTotals loaded;
  PaintTotals wiped;
};

// Adds b to a, growing a's slot list as needed.
inline void accumulate(PaintTotals& a, const PaintTotals& b) {
  a.volume += b.volume;
  if (a.pigment.size() < b.pigment.size()) a.pigment.resize(b.pigment.size(), 0.0);
  for (std::size_t s = 0; s < b.pigment.size(); ++s) a.pigment[s] += b.pigment[s];
}

}  // namespace impasto::paintcore
