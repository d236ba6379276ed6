#include "cavity_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace impasto::cracks::detail {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Smallest root t > t_min of a t^2 + 2 b t + c = 0 accepted by `ok`, or +inf.
template <class Accept>
double smallest_root(double a, double b, double c, double t_min, Accept ok) {
  if (a <= 0.0) return std::numeric_limits<double>::infinity();
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::numeric_limits<double>::infinity();
  const double s = std::sqrt(disc);
  const double t0 = (-b - s) / a, t1 = (-b + s) / a;
  if (t0 > t_min && ok(t0)) return t0;
  if (t1 > t_min && ok(t1)) return t1;
  return std::numeric_limits<double>::infinity();
}
}  // namespace

CavityGeometry::CavityGeometry(CavityShape shape, const CavityDims& dims)
    : shape_(shape), L_(dims.depth_mm), R_(dims.half_width_mm) {
  validate(dims);
  t_min_ = 1e-10 * (L_ + R_);
  if (shape == CavityShape::ArcGroove || shape == CavityShape::SpherePit) {
    radius_ = (R_ * R_ + L_ * L_) / (2.0 * L_);
    centre_z_ = radius_ - L_;
  }
}

std::optional<WallPoint> CavityGeometry::trace(Vec3 o, Vec3 d) const {
  if (L_ <= 0.0) return std::nullopt;  // no depth: every ray leaves at once
  switch (shape_) {
    case CavityShape::ArcGroove:
      return trace_arc(o, d);
    case CavityShape::VGroove:
    case CavityShape::BoxGroove:
      return trace_segments(o, d);
    case CavityShape::SpherePit:
      return trace_sphere(o, d);
    case CavityShape::ConePit:
      return trace_cone(o, d);
    case CavityShape::CylinderPit:
      return trace_cylinder(o, d);
  }
  return std::nullopt;
}

std::optional<WallPoint> CavityGeometry::trace_arc(Vec3 o, Vec3 d) const {
  // Circle in the x-z plane: x^2 + (z - zc)^2 = r^2, below z = 0.
  const double ox = o.x, oz = o.z - centre_z_;
  const double a = d.x * d.x + d.z * d.z;
  const double b = ox * d.x + oz * d.z;
  const double c = ox * ox + oz * oz - radius_ * radius_;
  // From inside the circle the far root is the wall; the ray escapes if it is above z = 0.
  if (a <= 0.0) return std::nullopt;
  const double disc = std::max(b * b - a * c, 0.0);
  const double t = (-b + std::sqrt(disc)) / a;
  if (!(t > t_min_)) return std::nullopt;
  const Vec3 p = o + t * d;
  if (p.z >= 0.0) return std::nullopt;
  return WallPoint{p, normalized(Vec3{-p.x, 0.0, centre_z_ - p.z})};
}

std::optional<WallPoint> CavityGeometry::trace_segments(Vec3 o, Vec3 d) const {
  // Walls as 2-D segments (x, z) with inward normals; V: two sides; box: sides and bottom.
  struct Segment {
    double x0, z0, x1, z1, nx, nz;
  };
  const double s = std::hypot(R_, L_);
  const Segment v[] = {{-R_, 0.0, 0.0, -L_, L_ / s, R_ / s}, {R_, 0.0, 0.0, -L_, -L_ / s, R_ / s}};
  const Segment box[] = {
      {-R_, 0.0, -R_, -L_, 1.0, 0.0}, {R_, 0.0, R_, -L_, -1.0, 0.0}, {-R_, -L_, R_, -L_, 0.0, 1.0}};
  const Segment* begin = shape_ == CavityShape::VGroove ? v : box;
  const Segment* end = shape_ == CavityShape::VGroove ? v + 2 : box + 3;
  double best = std::numeric_limits<double>::infinity();
  const Segment* hit = nullptr;
  for (const Segment* seg = begin; seg != end; ++seg) {
    const double facing = seg->nx * d.x + seg->nz * d.z;
    if (facing >= 0.0) continue;  // moving away from (or along) the wall's inner face
    const double t = (seg->nx * (seg->x0 - o.x) + seg->nz * (seg->z0 - o.z)) / facing;
    if (!(t > t_min_) || t >= best) continue;
    // Position along the segment, with a tolerance so that corners never leak rays.
    const double ex = seg->x1 - seg->x0, ez = seg->z1 - seg->z0;
    const double along =
        ((o.x + t * d.x - seg->x0) * ex + (o.z + t * d.z - seg->z0) * ez) / (ex * ex + ez * ez);
    if (along < -1e-9 || along > 1.0 + 1e-9) continue;
    best = t;
    hit = seg;
  }
  if (hit == nullptr) return std::nullopt;
  const Vec3 p = o + best * d;
  if (p.z >= 0.0) return std::nullopt;
  return WallPoint{p, Vec3{hit->nx, 0.0, hit->nz}};
}

std::optional<WallPoint> CavityGeometry::trace_sphere(Vec3 o, Vec3 d) const {
  const Vec3 oc{o.x, o.y, o.z - centre_z_};
  const double a = dot(d, d);
  const double b = dot(oc, d);
  const double c = dot(oc, oc) - radius_ * radius_;
  const double disc = std::max(b * b - a * c, 0.0);
  const double t = (-b + std::sqrt(disc)) / a;
  if (!(t > t_min_)) return std::nullopt;
  const Vec3 p = o + t * d;
  if (p.z >= 0.0) return std::nullopt;
  return WallPoint{p, normalized(Vec3{-p.x, -p.y, centre_z_ - p.z})};
}

std::optional<WallPoint> CavityGeometry::trace_cone(Vec3 o, Vec3 d) const {
  // x^2 + y^2 = k^2 (z + L)^2 with k = R / L, for -L <= z <= 0.
  const double k2 = (R_ / L_) * (R_ / L_);
  const double w = o.z + L_;
  const double a = d.x * d.x + d.y * d.y - k2 * d.z * d.z;
  const double b = o.x * d.x + o.y * d.y - k2 * w * d.z;
  const double c = o.x * o.x + o.y * o.y - k2 * w * w;
  auto on_wall = [&](double t) {
    const double z = o.z + t * d.z;
    return z >= -L_ && z < 0.0;
  };
  double t = std::numeric_limits<double>::infinity();
  if (std::abs(a) > 1e-14 * dot(d, d)) {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double s = std::sqrt(disc);
      for (double root : {(-b - s) / a, (-b + s) / a}) {
        if (root > t_min_ && root < t && on_wall(root)) t = root;
      }
    }
  } else if (b != 0.0) {  // direction along a generator: one root
    const double root = -c / (2.0 * b);
    if (root > t_min_ && on_wall(root)) t = root;
  }
  if (!std::isfinite(t)) return std::nullopt;
  const Vec3 p = o + t * d;
  return WallPoint{p, normalized(Vec3{-p.x, -p.y, k2 * (p.z + L_)})};
}

std::optional<WallPoint> CavityGeometry::trace_cylinder(Vec3 o, Vec3 d) const {
  const double a = d.x * d.x + d.y * d.y;
  const double b = o.x * d.x + o.y * d.y;
  const double c = o.x * o.x + o.y * o.y - R_ * R_;
  double t_side = smallest_root(a, b, c, t_min_, [&](double t) {
    const double z = o.z + t * d.z;
    return z >= -L_ && z < 0.0;
  });
  double t_bottom = std::numeric_limits<double>::infinity();
  if (d.z < 0.0) {
    const double t = (-L_ - o.z) / d.z;
    const double x = o.x + t * d.x, y = o.y + t * d.y;
    if (t > t_min_ && x * x + y * y <= R_ * R_ * (1.0 + 1e-12)) t_bottom = t;
  }
  if (t_bottom <= t_side && std::isfinite(t_bottom)) {
    return WallPoint{o + t_bottom * d, Vec3{0.0, 0.0, 1.0}};
  }
  if (!std::isfinite(t_side)) return std::nullopt;
  const Vec3 p = o + t_side * d;
  return WallPoint{p, normalized(Vec3{-p.x, -p.y, 0.0})};
}

WallPoint CavityGeometry::sample_wall(double u1, double u2) const {
  const double L = L_, R = R_;
  switch (shape_) {
    case CavityShape::ArcGroove: {
      const double beta = 2.0 * std::atan2(L, R);
      const double angle = (2.0 * u1 - 1.0) * beta;  // from the deepest point
      const Vec3 p{radius_ * std::sin(angle), 0.0, centre_z_ - radius_ * std::cos(angle)};
      return {p, Vec3{-std::sin(angle), 0.0, std::cos(angle)}};
    }
    case CavityShape::VGroove: {
      const double side = u1 < 0.5 ? -1.0 : 1.0;
      const double along = u1 < 0.5 ? 2.0 * u1 : 2.0 * u1 - 1.0;  // 0 at the apex
      const double s = std::hypot(R, L);
      return {Vec3{side * R * along, 0.0, -L + L * along}, Vec3{-side * L / s, 0.0, R / s}};
    }
    case CavityShape::BoxGroove: {
      const double total = 2.0 * R + 2.0 * L;
      const double x = u1 * total;
      if (x < 2.0 * R) return {Vec3{x - R, 0.0, -L}, Vec3{0.0, 0.0, 1.0}};
      const double side = x < 2.0 * R + L ? -1.0 : 1.0;
      const double depth = x < 2.0 * R + L ? x - 2.0 * R : x - 2.0 * R - L;
      return {Vec3{side * R, 0.0, -depth}, Vec3{-side, 0.0, 0.0}};
    }
    case CavityShape::SpherePit: {
      // Archimedes: on a sphere, area is uniform in z.
      const double z = -L * u1;
      const double rho =
          std::sqrt(std::max(radius_ * radius_ - (z - centre_z_) * (z - centre_z_), 0.0));
      const double phi = kTwoPi * u2;
      const Vec3 p{rho * std::cos(phi), rho * std::sin(phi), z};
      return {p, normalized(Vec3{-p.x, -p.y, centre_z_ - z})};
    }
    case CavityShape::ConePit: {
      const double rho = R * std::sqrt(u1);  // area element grows with rho
      const double phi = kTwoPi * u2;
      const Vec3 p{rho * std::cos(phi), rho * std::sin(phi), -L + L * rho / R};
      const double s = std::hypot(R, L);
      return {p, Vec3{-L / s * std::cos(phi), -L / s * std::sin(phi), R / s}};
    }
    case CavityShape::CylinderPit: {
      const double bottom = R * R / (R * R + 2.0 * R * L);
      const double phi = kTwoPi * u2;
      if (u1 < bottom) {
        const double rho = R * std::sqrt(u1 / bottom);
        return {Vec3{rho * std::cos(phi), rho * std::sin(phi), -L}, Vec3{0.0, 0.0, 1.0}};
      }
      const double z = -L * (u1 - bottom) / (1.0 - bottom);
      return {Vec3{R * std::cos(phi), R * std::sin(phi), z},
              Vec3{-std::cos(phi), -std::sin(phi), 0.0}};
    }
  }
  return {};
}

Vec3 CavityGeometry::sample_opening(double u1, double u2) const {
  if (is_groove(shape_)) return {(2.0 * u1 - 1.0) * R_, 0.0, 0.0};
  const double rho = R_ * std::sqrt(u1), phi = kTwoPi * u2;
  return {rho * std::cos(phi), rho * std::sin(phi), 0.0};
}

WallPoint CavityGeometry::deepest() const {
  return {Vec3{0.0, 0.0, -L_}, Vec3{0.0, 0.0, 1.0}};
}

Vec3 cosine_direction(Vec3 n, double u1, double u2) {
  // Malley: a uniform point on the unit disc lifted onto the hemisphere.
  const double r = std::sqrt(u1), phi = kTwoPi * u2;
  const double a = r * std::cos(phi), b = r * std::sin(phi);
  const double c = std::sqrt(std::max(0.0, 1.0 - u1));
  // Orthonormal basis around n (Duff et al. 2017, branchless).
  const double sign = std::copysign(1.0, n.z);
  const double p = -1.0 / (sign + n.z);
  const double q = n.x * n.y * p;
  const Vec3 t{1.0 + sign * n.x * n.x * p, sign * q, -sign * n.x};
  const Vec3 s{q, sign + n.y * n.y * p, -n.y};
  return a * t + b * s + c * n;
}

}  // namespace impasto::cracks::detail
