#include "impasto/cracks/close_up.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "cavity_geometry.hpp"

namespace impasto::cracks {

using detail::Vec3;

namespace {
constexpr double kPi = std::numbers::pi;

// Point on the profile of a groove section (x >= 0 half, deepest point at s = 0).
CavityWallPoint groove_point(CavityShape shape, double L, double R, double s, double sign) {
  switch (shape) {
    case CavityShape::ArcGroove: {
      const double beta = 2.0 * std::atan2(L, R);
      const double radius = (R * R + L * L) / (2.0 * L);
      const double a = sign * s * beta;
      return {{radius * std::sin(a), 0.0, radius - L - radius * std::cos(a)},
              {-std::sin(a), 0.0, std::cos(a)}};
    }
    case CavityShape::VGroove: {
      const double h = std::hypot(R, L);
      return {{sign * R * s, 0.0, -L + L * s}, {-sign * L / h, 0.0, R / h}};
    }
    default: {  // box: bottom half-width R, then the wall of height L
      const double along = s * (R + L);
      if (along <= R) return {{sign * along, 0.0, -L}, {0.0, 0.0, 1.0}};
      return {{sign * R, 0.0, -L + (along - R)}, {-sign, 0.0, 0.0}};
    }
  }
}

// Hottel's 2-D view factor from a strip element to the opening segment [-R, R] x {0}.
double groove_view_factor(const CavityWallPoint& p, double R) {
  const double nx = p.normal.x, nz = p.normal.z;
  auto sine_from_normal = [&](double rim_x) {
    const double dx = rim_x - p.position.x, dz = -p.position.z;
    const double len = std::hypot(dx, dz);
    if (len == 0.0) return 0.0;
    // sin of the angle from the normal, signed about the y axis.
    return (nz * dx - nx * dz) / len;
  };
  return std::clamp(0.5 * std::abs(sine_from_normal(R) - sine_from_normal(-R)), 0.0, 1.0);
}

// Element to a disc of radius R at z = 0 centred on the axis: contour integral
// F = (1 / 2 pi) \oint n . (r x dr) / |r|^2 over the rim (the disc lies wholly in front of
// the element in a convex cavity). The integrand is smooth and periodic, so the trapezoid
// rule converges geometrically except at the rim itself.
double disc_view_factor(const CavityWallPoint& p, double R) {
  constexpr int kNodes = 512;
  const Vec3 n = p.normal, o = p.position;
  double sum = 0.0;
  for (int i = 0; i < kNodes; ++i) {
    const double phi = 2.0 * kPi * (i + 0.5) / kNodes;
    const Vec3 r = Vec3{R * std::cos(phi), R * std::sin(phi), 0.0} - o;
    const Vec3 dr{-R * std::sin(phi), R * std::cos(phi), 0.0};
    const double r2 = dot(r, r);
    if (r2 > 0.0) sum += dot(n, cross(r, dr)) / r2;
  }
  return std::clamp(std::abs(sum / kNodes), 0.0, 1.0);
}

// Gauss-Legendre nodes and weights on [0, 1] (16 points).
struct GaussRule {
  std::array<double, 16> x, w;
};
const GaussRule& gauss16() {
  static const GaussRule rule = [] {
    GaussRule g{};
    constexpr int n = 16;
    for (int i = 0; i < n; ++i) {
      double t = std::cos(kPi * (i + 0.75) / (n + 0.5));  // Newton on P_n from Tricomi's guess
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = t;
        for (int k = 2; k <= n; ++k) {
          const double pk = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = pk;
        }
        dp = n * (t * p1 - p0) / (t * t - 1.0);
        const double step = p1 / dp;
        t -= step;
        if (std::abs(step) < 1e-16) break;
      }
      g.x[i] = 0.5 * (1.0 - t);
      g.w[i] = 1.0 / ((1.0 - t * t) * dp * dp);  // = (2 / ((1-t^2) P'^2)) / 2 on [0, 1]
    }
    return g;
  }();
  return rule;
}
}  // namespace

CavityWallPoint cavity_wall_point(CavityShape shape, const CavityDims& dims, double s,
                                  double side) {
  validate(dims);
  if (!(s >= 0.0 && s <= 1.0)) throw std::runtime_error("wall point s must be in [0, 1]");
  const double L = dims.depth_mm, R = dims.half_width_mm;
  if (is_groove(shape)) return groove_point(shape, L, R, s, side < 0.0 ? -1.0 : 1.0);
  // Pits: the profile in the (rho, z) half-plane, turned by the azimuth `side`.
  CavityWallPoint half;
  switch (shape) {
    case CavityShape::SpherePit:
      half = groove_point(CavityShape::ArcGroove, L, R, s, 1.0);
      break;
    case CavityShape::ConePit:
      half = groove_point(CavityShape::VGroove, L, R, s, 1.0);
      break;
    default:
      half = groove_point(CavityShape::BoxGroove, L, R, s, 1.0);
      break;
  }
  const double c = std::cos(side), sn = std::sin(side);
  return {{half.position.x * c, half.position.x * sn, half.position.z},
          {half.normal.x * c, half.normal.x * sn, half.normal.z}};
}

double opening_view_factor(CavityShape shape, const CavityDims& dims, const CavityWallPoint& p) {
  validate(dims);
  const double L = dims.depth_mm, R = dims.half_width_mm;
  if (is_groove(shape)) return groove_view_factor(p, R);
  if (shape == CavityShape::SpherePit) return R * R / (R * R + L * L);  // same for all points
  if (shape == CavityShape::CylinderPit) {
    const double depth = -p.position.z;
    const double rho = std::hypot(p.position.x, p.position.y);
    if (p.normal.z > 0.5) {
      // Bottom: element parallel to a disc, offset rho from its axis, at height L.
      const double h2 = depth * depth, a2 = R * R, r2 = rho * rho;
      return 0.5 *
             (1.0 - (h2 + r2 - a2) / std::sqrt((h2 + r2 + a2) * (h2 + r2 + a2) - 4 * a2 * r2));
    }
    // Wall, `depth` below the rim: X = depth / 2R, F = (X^2 + 1/2) / sqrt(X^2 + 1) - X.
    const double X = depth / (2.0 * R);
    return (X * X + 0.5) / std::sqrt(X * X + 1.0) - X;
  }
  return disc_view_factor(p, R);
}

double seed_view_factor_cylinder_bottom(const CavityDims& dims, double r_mm) {
  const double L = dims.depth_mm, R = dims.half_width_mm;
  const double t1 = std::atan((R - r_mm) / L), t2 = std::atan((R + r_mm) / L);
  return std::sin(t2) * std::sin(t2) - std::sin(t1) * std::sin(t1);
}

double seed_view_factor_cylinder_wall(const CavityDims& dims, double depth_below_rim_mm) {
  const double t1 = std::atan(depth_below_rim_mm / (2.0 * dims.half_width_mm));
  return 1.0 - std::sin(t1) * std::sin(t1);  // theta2 = pi / 2
}

double first_reflection_view_factor(CavityShape shape, const CavityDims& dims, double zenith_rad) {
  validate(dims);
  if (!(std::abs(zenith_rad) < kPi / 2)) {
    throw std::runtime_error("first_reflection_view_factor: zenith_rad must be in (-pi/2, pi/2)");
  }
  if (!(dims.depth_mm > 0.0)) return 1.0;
  const detail::CavityGeometry geo(shape, dims);
  const Vec3 beam{std::sin(zenith_rad), 0.0, -std::cos(zenith_rad)};
  const double R = dims.half_width_mm;
  const GaussRule& g = gauss16();
  auto f_at = [&](Vec3 entry) {
    const auto wall = geo.trace(entry, beam);
    if (!wall) return 1.0;
    return opening_view_factor(shape, dims, {wall->position, wall->normal});
  };
  double sum = 0.0;
  if (is_groove(shape)) {
    for (int i = 0; i < 16; ++i) {
      for (int half : {-1, 1}) sum += 0.5 * g.w[i] * f_at({half * R * g.x[i], 0.0, 0.0});
    }
    return sum;
  }
  // Pits: uniform over the disc, radius by Gauss (weight rho), azimuth by trapezoid.
  constexpr int kAzimuths = 32;
  for (int i = 0; i < 16; ++i) {
    const double rho = R * g.x[i];
    for (int k = 0; k < kAzimuths; ++k) {
      const double phi = 2.0 * kPi * (k + 0.5) / kAzimuths;
      sum +=
          g.w[i] * 2.0 * g.x[i] / kAzimuths * f_at({rho * std::cos(phi), rho * std::sin(phi), 0.0});
    }
  }
  return sum;
}

double cavity_point_radiosity(CavityShape shape, const CavityDims& dims, const CavityWallPoint& p,
                              double rho0, const CavityLighting& light) {
  const ViewFactors vf = view_factors(shape, dims);
  const CavityAreas areas = cavity_areas(shape, dims);
  const double f_point = opening_view_factor(shape, dims, p);
  const Vec3 sun = light.sun_direction;
  const double sun_cos_canvas = std::max(sun.z, 0.0);
  double sun_direct = 0.0;
  const double cos_wall = dot(p.normal, sun);
  if (cos_wall > 0.0 && sun_cos_canvas > 0.0) {
    const detail::CavityGeometry geo(shape, dims);
    const Vec3 start = p.position + (1e-9 * (dims.depth_mm + dims.half_width_mm)) * p.normal;
    if (!geo.trace(start, sun)) sun_direct = light.sun_irradiance * cos_wall;
  }
  const double flux_per_wall_area =
      areas.opening * (light.sky_irradiance + light.sun_irradiance * sun_cos_canvas) / areas.walls;
  const double walls = rho0 * flux_per_wall_area / (1.0 - rho0 * (1.0 - vf.G));
  return rho0 * (light.sky_irradiance * f_point + sun_direct + (1.0 - f_point) * walls);
}

}  // namespace impasto::cracks
