// The per-pixel geometry of §5.3.4–5.3.5: refraction into the binder (Eq. 8), angular sizes
// (Eq. 7), the mirroring flake, and the depth factor.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "impasto/flakes/sparkle_math.hpp"

namespace impasto::flakes {
namespace {

const Vec3 kUp{0, 0, 1};

// The unit vector `polar` radians from the zenith (+z), `azimuth` radians round from +x.
Vec3 direction_rad(double polar, double azimuth) {
  return {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
          std::cos(polar)};
}

TEST(SparkleMath, UnitIndexLeavesDirectionsAndSizesUnchanged) {
  for (double polar : {0.0, 0.4, 1.2, 1.5}) {
    const Vec3 V = direction_rad(polar, 0.7);
    const Vec3 v = refract_into_binder(V, kUp, 1.0);
    EXPECT_NEAR(v.x, V.x, 1e-15);
    EXPECT_NEAR(v.y, V.y, 1e-15);
    EXPECT_NEAR(v.z, V.z, 1e-15);
    EXPECT_NEAR(binder_angular_size(0.01, V.z, cos_inside_binder(V.z, 1.0), 1.0), 0.01, 1e-15);
  }
}

TEST(SparkleMath, RefractionObeysSnell) {
  const double eta = 1.5;
  // A tilted surface normal, to exercise the vector form of Eq. 8.
  const Vec3 n = normalized(Vec3{0.2, -0.1, 1.0});
  for (double polar : {0.1, 0.6, 1.3}) {
    const Vec3 V = normalized(direction_rad(polar, 2.0) + n);
    const Vec3 v = refract_into_binder(V, n, eta);
    EXPECT_NEAR(length(v), 1.0, 1e-12);
    const double cos_out = dot(V, n), cos_in = dot(v, n);
    EXPECT_NEAR(std::sqrt(1 - cos_out * cos_out), eta * std::sqrt(1 - cos_in * cos_in), 1e-12);
    EXPECT_NEAR(cos_in, cos_inside_binder(cos_out, eta), 1e-12);
    // V, v and n lie in one plane.
    const Vec3 cross{V.y * n.z - V.z * n.y, V.z * n.x - V.x * n.z, V.x * n.y - V.y * n.x};
    EXPECT_NEAR(dot(cross, v), 0.0, 1e-12);
  }
}

TEST(SparkleMath, AngularSizeShrinksByTheSolidAngleRatio) {
  const double eta = 1.5;
  EXPECT_NEAR(binder_angular_size(0.01, 1.0, 1.0, eta), 0.01 / eta, 1e-15);
  // Δᵢ² / Δ² = dΩ_in / dΩ_out = cos ϑ / (η² cos ϑ_p), checked by a finite difference of Snell.
  const double polar = 1.0, d = 1e-6;
  const double in0 = std::asin(std::sin(polar) / eta), in1 = std::asin(std::sin(polar + d) / eta);
  const double ratio = std::sin(in0) * (in1 - in0) / (std::sin(polar) * d);  // dΩ_in / dΩ_out
  const double size = binder_angular_size(1.0, std::cos(polar), std::cos(in0), eta);
  EXPECT_NEAR(size * size, ratio, 1e-5);
}

TEST(SparkleMath, TheSpecularFlakeMirrorsLightIntoView) {
  const Vec3 light = direction_rad(0.5, 0.0), view = direction_rad(0.3, 2.5);
  const SpecularFlake f = specular_flake(view, light, kUp);
  const Vec3 mirrored = 2.0 * dot(light, f.normal) * f.normal - light;
  EXPECT_NEAR(mirrored.x, view.x, 1e-12);
  EXPECT_NEAR(mirrored.y, view.y, 1e-12);
  EXPECT_NEAR(mirrored.z, view.z, 1e-12);
  EXPECT_NEAR(f.cos_alpha, dot(f.normal, view), 1e-12);
  EXPECT_NEAR(f.cos_beta, f.normal.z, 1e-12);
  // Light straight down and view straight up: the flat flake, α = β = 0.
  const SpecularFlake flat = specular_flake(kUp, kUp, kUp);
  EXPECT_DOUBLE_EQ(flat.cos_alpha, 1.0);
  EXPECT_DOUBLE_EQ(flat.cos_beta, 1.0);
}

TEST(SparkleMath, DirectFractionLimits) {
  EXPECT_EQ(direct_fraction(0.0, 1.0), 1.0);
  EXPECT_NEAR(direct_fraction(1e-9, 0.1), 1.0, 1e-9);
  EXPECT_NEAR(direct_fraction(2.0, 0.5), (1 - std::exp(-1.0)), 1e-15);
  EXPECT_NEAR(direct_fraction(1000.0, 1.0), 1e-3, 1e-12);
}

TEST(SparkleMath, MirrorProbabilityIsEquationFour) {
  // P(β) / 2π per steradian times the cone of normals π Δ² / (4 cos α).
  const double density = 30.0, delta = 0.004, cos_alpha = 0.8;
  const double cone = std::numbers::pi * delta * delta / (4 * cos_alpha);
  EXPECT_NEAR(mirror_probability(density, delta, cos_alpha),
              density / (2 * std::numbers::pi) * cone, 1e-15);
}

}  // namespace
}  // namespace impasto::flakes
