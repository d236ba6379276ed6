#pragma once
// Ray tracing inside a cavity: the wall surfaces of the six shapes, exact intersections,
// area-uniform wall samples and cosine-weighted diffuse directions. Used by the Monte
// Carlo reference and by close-up shadow tests. Coordinates in mm: opening at z = 0,
// cavity below; grooves are extruded along y, so their rays are traced in the x-z plane.
#include <optional>

#include "impasto/cracks/cavity.hpp"
#include "vec3.hpp"

namespace impasto::cracks::detail {

struct WallPoint {
  Vec3 position;
  Vec3 normal;  // unit, pointing into the cavity
};

class CavityGeometry {
 public:
  CavityGeometry(CavityShape shape, const CavityDims& dims);

  // The nearest wall point hit by origin + t * direction with t > a small epsilon, or
  // nothing when the ray leaves through the opening (the cavity is convex: a ray that
  // hits no wall escapes).
  std::optional<WallPoint> trace(Vec3 origin, Vec3 direction) const;

  // A wall point distributed uniformly over the wall area, from two uniforms in (0, 1).
  WallPoint sample_wall(double u1, double u2) const;
  // A point distributed uniformly over the opening (z = 0).
  Vec3 sample_opening(double u1, double u2) const;
  // The deepest wall element, facing the opening (+z).
  WallPoint deepest() const;

  CavityShape shape() const { return shape_; }
  double depth() const { return L_; }
  double half_width() const { return R_; }

 private:
  std::optional<WallPoint> trace_arc(Vec3 o, Vec3 d) const;
  std::optional<WallPoint> trace_segments(Vec3 o, Vec3 d) const;
  std::optional<WallPoint> trace_sphere(Vec3 o, Vec3 d) const;
  std::optional<WallPoint> trace_cone(Vec3 o, Vec3 d) const;
  std::optional<WallPoint> trace_cylinder(Vec3 o, Vec3 d) const;

  CavityShape shape_;
  double L_, R_;
  double radius_ = 0.0;    // circle or sphere radius (arc groove, sphere pit)
  double centre_z_ = 0.0;  // its centre on the axis
  double t_min_;           // self-intersection guard, relative to the cavity size
};

// A cosine-weighted direction about the unit normal n, from two uniforms.
Vec3 cosine_direction(Vec3 n, double u1, double u2);

}  // namespace impasto::cracks::detail
