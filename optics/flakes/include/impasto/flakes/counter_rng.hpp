#pragma once
// Counter-based random numbers: a hash of (canvas cell, flake-orientation cell) seeds a
// stream, so a painting sparkles the same in every frame and on every thread, and the GPU
// can reproduce it. The hash is pcg4d (Jarzynski, Olano, "Hash Functions for GPU
// Rendering", JCGT 2020), written so each line maps to GLSL uvec4 arithmetic.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace impasto::flakes {

using Uint4 = std::array<std::uint32_t, 4>;

inline Uint4 pcg4d(Uint4 v) {
  for (auto& x : v) x = x * 1664525u + 1013904223u;
  v[0] += v[1] * v[3];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  v[3] += v[1] * v[2];
  for (auto& x : v) x ^= x >> 16u;
  v[0] += v[1] * v[3];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  v[3] += v[1] * v[2];
  return v;
}

// A stream of uniform deviates for one key: the first block of four numbers is pcg4d(key),
// block b > 0 is pcg4d(first block + (b, 0, 0, 0)). Most cells need one number only.
class CounterRng {
 public:
  explicit CounterRng(Uint4 key) : first_(pcg4d(key)), block_(first_) {}

  // Uniform in (0, 1), never exactly 0 or 1.
  double uniform() {
    if (used_ == 4) {
      ++counter_;
      block_ = pcg4d({first_[0] + counter_, first_[1], first_[2], first_[3]});
      used_ = 0;
    }
    return (static_cast<double>(block_[used_++]) + 0.5) * 0x1p-32;
  }

  // Standard normal deviate (Box–Muller, one of the pair).
  double normal() {
    const double u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  Uint4 first_;
  Uint4 block_;
  std::uint32_t counter_ = 0;
  int used_ = 0;
};

// Number of sparkles for an expected count `mean` ≥ 0 (Ershov et al. §5.3.5): a Bernoulli
// trial when mean < 0.1, a Poisson deviate otherwise (inversion below 10, Hörmann's
// transformed rejection PTRS above).
int sample_sparkle_count(CounterRng& rng, double mean);

}  // namespace impasto::flakes
