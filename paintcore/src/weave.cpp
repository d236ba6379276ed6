#include "impasto/paintcore/weave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

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

constexpr double pi = std::numbers::pi;

// What one coordinate alone decides: the position across the threads (u or v), the thread
// (iu or iv), its profile and its thickness. The same expressions as canvas_weave_height_mm.
struct Axis {
  double t = 0, it = 0, profile = 0, thickness = 0;
};

Axis axis(std::uint64_t seed, double mm, std::uint64_t direction) {
  Axis a;
  a.t = mm / kWeaveThreadPitchMm;
  a.it = std::floor(a.t);
  a.profile = std::sqrt(std::sin(pi * (a.t - a.it)));
  a.thickness = thread_thickness(seed, static_cast<std::int64_t>(a.it), direction);
  return a;
}

}  // namespace

void canvas_weave_heights_mm(std::uint64_t seed, const double* x_mm, int nx, const double* y_mm,
                             int ny, float* out, int stride) {
  if (seed == 0) {
    for (int y = 0; y < ny; ++y) std::fill(out + y * stride, out + y * stride + nx, 0.0f);
    return;
  }
  std::vector<Axis> columns(static_cast<std::size_t>(nx)), rows(static_cast<std::size_t>(ny));
  for (int x = 0; x < nx; ++x) columns[static_cast<std::size_t>(x)] = axis(seed, x_mm[x], 0);
  for (int y = 0; y < ny; ++y) rows[static_cast<std::size_t>(y)] = axis(seed, y_mm[y], 1);
  // The weft's undulation over the grid, column by column: it changes only where the row's
  // thread does, so runs of rows on one weft thread share it.
  std::vector<double> cross(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int x = 0; x < nx; ++x) {
    const Axis& u = columns[static_cast<std::size_t>(x)];
    double it = std::numeric_limits<double>::quiet_NaN(), value = 0;
    for (int y = 0; y < ny; ++y) {
      const Axis& v = rows[static_cast<std::size_t>(y)];
      if (v.it != it) {
        it = v.it;
        value = 0.225 * std::cos(pi * (u.t - 0.5 + it));
      }
      cross[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
            static_cast<std::size_t>(x)] = value;
    }
  }
  for (int y = 0; y < ny; ++y) {
    const Axis& v = rows[static_cast<std::size_t>(y)];
    double it = std::numeric_limits<double>::quiet_NaN(), undulation = 0;
    for (int x = 0; x < nx; ++x) {
      const Axis& u = columns[static_cast<std::size_t>(x)];
      if (u.it != it) {
        it = u.it;
        undulation = 0.225 * std::cos(pi * (v.t - 0.5 + it));
      }
      const double cross_undulation =
          cross[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                static_cast<std::size_t>(x)];
      const double warp = u.thickness * u.profile * (0.775 + undulation);
      const double weft = v.thickness * v.profile * (0.775 - cross_undulation);
      out[y * stride + x] = static_cast<float>(kWeaveAmplitudeMm * std::max(warp, weft));
    }
  }
}

float canvas_weave_height_mm(std::uint64_t seed, double x_mm, double y_mm) {
  if (seed == 0) return 0.0f;
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
