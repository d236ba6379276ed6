#include "impasto/paintcore/weave.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impasto::paintcore {
namespace {

// splitmix64: a well-mixed hash of the seed and a thread index.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Relative thickness of thread `index` of one direction, in [0.8, 1.2].
double thread_thickness(std::uint64_t seed, std::int64_t index, std::uint64_t direction) {
  const std::uint64_t h = mix(seed ^ mix(static_cast<std::uint64_t>(index) * 2 + direction));
  return 0.8 + 0.4 * static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace

float canvas_weave_height_mm(std::uint64_t seed, double x_mm, double y_mm) {
  if (seed == 0) return 0.0f;
  constexpr double pi = std::numbers::pi;
  const double u = x_mm / kWeaveThreadPitchMm;  // across the warp threads (columns)
  const double v = y_mm / kWeaveThreadPitchMm;  // across the weft threads (rows)
  const double iu = std::floor(u);
  const double iv = std::floor(v);
  // Cross-section of a thread: a rounded bump, zero at its edges.
  const double warp_profile = std::sqrt(std::sin(pi * (u - iu)));
  const double weft_profile = std::sqrt(std::sin(pi * (v - iv)));
  // Plain weave: a warp thread rises over one weft and dips under the next, smoothly.
  const double undulation = 0.225 * std::cos(pi * (v - 0.5 + iu));
  const double cross_undulation = 0.225 * std::cos(pi * (u - 0.5 + iv));
  const double warp = thread_thickness(seed, static_cast<std::int64_t>(iu), 0) * warp_profile *
                      (0.775 + undulation);
  const double weft = thread_thickness(seed, static_cast<std::int64_t>(iv), 1) * weft_profile *
                      (0.775 - cross_undulation);
  return static_cast<float>(kWeaveAmplitudeMm * std::max(warp, weft));
}

}  // namespace impasto::paintcore
