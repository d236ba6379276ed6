#include "impasto/cracks/monte_carlo.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "cavity_geometry.hpp"
#include "impasto/cracks/philox_rng.hpp"

namespace impasto::cracks {

using detail::CavityGeometry;
using detail::Vec3;

namespace {
// Random streams: one per use, so that no two draw the same numbers.
constexpr std::uint32_t kStreamPaths = 1, kStreamViewF = 2, kStreamViewG = 3, kStreamPoint = 4;
constexpr std::uint64_t kPathsPerBlock = 4096;

// Number of reflections before the path leaves, or -1 if it is still inside.
int follow_path(const CavityGeometry& geo, const Illumination& light, std::uint64_t seed,
                std::uint64_t path, int max_bounces) {
  const UniformBlock start = uniforms(seed, kStreamPaths, path, 0);
  Vec3 origin = geo.sample_opening(start.u[0], start.u[1]);
  Vec3 direction;
  if (light.kind == Illumination::Kind::UniformDiffuse) {
    direction = detail::cosine_direction(Vec3{0.0, 0.0, -1.0}, start.u[2], start.u[3]);
  } else {
    direction = {std::sin(light.zenith_rad), 0.0, -std::cos(light.zenith_rad)};
  }
  for (int bounce = 1; bounce <= max_bounces; ++bounce) {
    const auto wall = geo.trace(origin, direction);
    if (!wall) return bounce - 1;
    const UniformBlock u = uniforms(seed, kStreamPaths, path, static_cast<std::uint32_t>(bounce));
    origin = wall->position;
    direction = detail::cosine_direction(wall->normal, u.u[0], u.u[1]);
  }
  return geo.trace(origin, direction) ? -1 : max_bounces;
}
}  // namespace

double EscapeHistogram::escape_probability(int n) const {
  if (paths == 0 || n < 0 || n >= static_cast<int>(escaped_after.size())) return 0.0;
  return static_cast<double>(escaped_after[n]) / static_cast<double>(paths);
}

double EscapeHistogram::apparent_reflectance(double rho0) const {
  if (paths == 0) return 0.0;
  double sum = 0.0, power = 1.0;
  for (std::uint64_t count : escaped_after) {
    sum += static_cast<double>(count) * power;
    power *= rho0;
  }
  return sum / static_cast<double>(paths);
}

double EscapeHistogram::standard_error(double rho0) const {
  if (paths < 2) return 0.0;
  const double mean = apparent_reflectance(rho0);
  const double mean_sq = apparent_reflectance(rho0 * rho0);
  const double n = static_cast<double>(paths);
  return std::sqrt(std::max(mean_sq - mean * mean, 0.0) / (n - 1.0));
}

EscapeHistogram trace_cavity(CavityShape shape, const CavityDims& dims, const Illumination& light,
                             const MonteCarloSettings& settings) {
  if (settings.max_bounces < 1) throw std::runtime_error("max_bounces must be >= 1");
  if (light.kind == Illumination::Kind::Directional &&
      !(std::abs(light.zenith_rad) < std::numbers::pi / 2)) {
    throw std::runtime_error("directional light zenith_rad must be in (-pi/2, pi/2)");
  }
  if (!(dims.depth_mm > 0.0)) throw std::runtime_error("a traced cavity needs depth_mm > 0");
  const CavityGeometry geo(shape, dims);
  const std::uint64_t blocks = (settings.paths + kPathsPerBlock - 1) / kPathsPerBlock;
  const std::size_t bins = static_cast<std::size_t>(settings.max_bounces) + 1;
  // One histogram per block; counts are integers, so summing them is exact in any order.
  std::vector<std::vector<std::uint64_t>> partial(blocks, std::vector<std::uint64_t>(bins + 1));
  tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, blocks), [&](const auto& range) {
    for (std::uint64_t b = range.begin(); b != range.end(); ++b) {
      const std::uint64_t end = std::min(settings.paths, (b + 1) * kPathsPerBlock);
      for (std::uint64_t path = b * kPathsPerBlock; path < end; ++path) {
        const int n = follow_path(geo, light, settings.seed, path, settings.max_bounces);
        ++partial[b][n < 0 ? bins : static_cast<std::size_t>(n)];
      }
    }
  });
  EscapeHistogram h;
  h.paths = settings.paths;
  h.escaped_after.assign(bins, 0);
  for (const auto& p : partial) {
    for (std::size_t n = 0; n < bins; ++n) h.escaped_after[n] += p[n];
    h.unfinished += p[bins];
  }
  return h;
}

ViewFactorEstimate estimate_view_factors(CavityShape shape, const CavityDims& dims,
                                         std::uint64_t samples, std::uint64_t seed) {
  const CavityGeometry geo(shape, dims);
  // Start a hair above the deepest point so that directions into an apex's walls are seen
  // as blocked rather than grazing.
  const detail::WallPoint deepest = geo.deepest();
  const Vec3 above_deepest =
      deepest.position + (1e-7 * (dims.depth_mm + dims.half_width_mm)) * deepest.normal;
  std::uint64_t escaped_f = 0, escaped_g = 0;
  for (std::uint64_t i = 0; i < samples; ++i) {
    const UniformBlock f = uniforms(seed, kStreamViewF, i, 0);
    if (!geo.trace(above_deepest, detail::cosine_direction(deepest.normal, f.u[0], f.u[1]))) {
      ++escaped_f;
    }
    const UniformBlock g = uniforms(seed, kStreamViewG, i, 0);
    const detail::WallPoint w = geo.sample_wall(g.u[0], g.u[1]);
    if (!geo.trace(w.position, detail::cosine_direction(w.normal, g.u[2], g.u[3]))) ++escaped_g;
  }
  const double n = static_cast<double>(std::max<std::uint64_t>(samples, 1));
  const double pf = static_cast<double>(escaped_f) / n, pg = static_cast<double>(escaped_g) / n;
  return {{pf, pg}, {std::sqrt(pf * (1.0 - pf) / n), std::sqrt(pg * (1.0 - pg) / n)}};
}

std::array<double, 2> estimate_opening_view_factor(CavityShape shape, const CavityDims& dims,
                                                   const CavityWallPoint& point,
                                                   std::uint64_t samples, std::uint64_t seed) {
  const CavityGeometry geo(shape, dims);
  const Vec3 n = point.normal;
  const Vec3 start = point.position + (1e-7 * (dims.depth_mm + dims.half_width_mm)) * n;
  std::uint64_t escaped = 0;
  for (std::uint64_t i = 0; i < samples; ++i) {
    const UniformBlock u = uniforms(seed, kStreamPoint, i, 0);
    if (!geo.trace(start, detail::cosine_direction(n, u.u[0], u.u[1]))) ++escaped;
  }
  const double count = static_cast<double>(std::max<std::uint64_t>(samples, 1));
  const double p = static_cast<double>(escaped) / count;
  return {p, std::sqrt(p * (1.0 - p) / count)};
}

}  // namespace impasto::cracks
