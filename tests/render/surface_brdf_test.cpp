// The rough-surface BRDF (surface_brdf.hpp) against what physics demands of any BRDF and
// against its own limits: reciprocity, no more light out than in (white furnace over every
// incidence and wavelength), the mirror's Fresnel reflectance when smooth, the geometric
// (facet) limit of the kernel and Lambert's limit of the BRDF when very rough.
#include "impasto/render/surface_brdf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace impasto::render::surface;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<double, 3> direction(double cos_theta, double phi) {
  const double s = std::sqrt(1.0 - cos_theta * cos_theta);
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

GhsParams params(Roughness r, double wavelength_nm, bool fresnel = true, double source = 0.013) {
  GhsParams p;
  p.roughness = r;
  p.wavelength_nm = wavelength_nm;
  p.index = binder_index(wavelength_nm);
  p.source_sigma = source;
  p.fresnel = fresnel;
  return p;
}

const std::vector<Roughness> kRoughnesses{finish_roughness(Finish::gloss),
                                          finish_roughness(Finish::satin),
                                          finish_roughness(Finish::matte),
                                          {0.3, 1.0},
                                          {0.05, 0.5}};

}  // namespace

TEST(Fresnel, HeadOnGrazingAndMonotone) {
  for (double n : {1.33, 1.48, 1.6}) {
    EXPECT_NEAR(fresnel_dielectric(1.0, n), std::pow((n - 1.0) / (n + 1.0), 2.0), 1e-12);
    EXPECT_NEAR(fresnel_dielectric(0.0, n), 1.0, 1e-12);
    double last = fresnel_dielectric(1.0, n);
    for (double c = 0.95; c > 0.0; c -= 0.05) {
      const double f = fresnel_dielectric(c, n);
      EXPECT_GE(f, last - 1e-12) << "cos " << c;
      last = f;
    }
  }
  // Brewster's angle: the p part vanishes, so F = rs²/2 there.
  const double n = 1.5;
  const double cos_b = std::cos(std::atan(n));
  const double cos_t = std::sqrt(1.0 - (1.0 - cos_b * cos_b) / (n * n));
  const double rs = (cos_b - n * cos_t) / (cos_b + n * cos_t);
  EXPECT_NEAR(fresnel_dielectric(cos_b, n), 0.5 * rs * rs, 1e-12);
}

TEST(Fresnel, BinderDispersesNormally) {
  EXPECT_NEAR(binder_index(589.3), 1.48, 1e-12);
  EXPECT_GT(binder_index(400.0), binder_index(550.0));
  EXPECT_GT(binder_index(550.0), binder_index(700.0));
  EXPECT_NEAR(binder_index(486.1) - binder_index(656.3), 0.0078, 0.003);  // Abbe number ~ 60
}

TEST(GhsKernel, IntegratesToOneOverThePlane) {
  // Without the disc's cut (a lobe well inside it) the Poisson mixture is a probability density.
  for (const Roughness& r : {Roughness{0.01, 4.0}, Roughness{0.08, 4.0}, Roughness{0.2, 20.0}}) {
    const GhsParams p = params(r, 550.0);
    const double total = GhsBrdf::integrate_disc(1.0, 1e-4, [&](double x, double y) {
      return ghs_kernel(p, 1.0, 1.0, std::hypot(x, y));  // g frozen at head-on
    });
    EXPECT_NEAR(total, 1.0, 2e-3) << r.rms_um << " " << r.correlation_um;
  }
}

TEST(GhsBrdf, Reciprocal) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.02, 1.0);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (const Roughness& r : kRoughnesses) {
    for (double wavelength : {480.0}) {
      const GhsBrdf brdf(params(r, wavelength));
      for (int k = 0; k < 50; ++k) {
        const auto l = direction(unit(random), angle(random));
        const auto v = direction(unit(random), angle(random));
        const double forward = brdf.eval(l, v);
        const double backward = brdf.eval(v, l);
        EXPECT_NEAR(forward, backward, 1e-12 * std::max(1.0, forward));
        EXPECT_GE(forward, 0.0);
      }
    }
  }
}

TEST(GhsBrdf, WhiteFurnaceNeverReflectsMoreThanArrives) {
  // A perfect reflector (F = 1): every incidence angle and wavelength reflects what arrives,
  // no more, and (the light single scattering misses scattered again) no less.
  for (const Roughness& r : kRoughnesses) {
    // The ends of the visible, one without sub-cell slopes and one with steep ones.
    for (const auto& [wavelength, subcell] : {std::pair{380.0, 0.0}, std::pair{750.0, 0.2}}) {
      GhsParams p = params(r, wavelength, false);
      p.subcell_slope_rms = subcell;
      const GhsBrdf brdf(p);
      // From the tables' second entry (at cos θ = 0 the tables hold 0: no light arrives).
      for (int k = 2; k <= 40; ++k) {
        const double mu = k / 40.0;
        EXPECT_LE(brdf.albedo(mu), 1.0 + 3e-3) << r.rms_um << " um, " << wavelength << " nm";
        EXPECT_GT(brdf.albedo(mu), 0.97) << r.rms_um << " um, " << wavelength << " nm, cos " << mu;
      }
      EXPECT_LE(brdf.hemispherical_albedo(), 1.0 + 3e-3);
      EXPECT_GT(brdf.hemispherical_albedo(), 0.98);
    }
  }
}

TEST(GhsBrdf, RoughLimitIsLambert) {
  // As the slopes grow, shadowing leaves single scattering ever less of the light and the
  // multiply scattered lobe takes it over: a perfect reflector's BRDF tends to 1/π for every
  // pair of directions (docs/surface.md, "The limits"). Head on, within the tables' last
  // interval (14°), facets facing the viewer stay unmasked; the pairs stop short of it. With
  // the binder's Fresnel each further bounce sends most of the light into the paint: the
  // surface's own reflection fades and the paint's Lambertian body is what is seen.
  double last_error = 1e300, last_albedo = 1e300;
  for (double rms : {4.0, 16.0, 64.0}) {
    const GhsBrdf perfect(params({rms, 4.0}, 550.0, false));
    double error = 0.0;
    for (double mu_i : {0.2, 0.5, 0.8, 0.9}) {
      for (double mu_o : {0.2, 0.5, 0.8, 0.9}) {
        for (double phi : {0.0, 1.5, kPi}) {
          const double f = perfect.eval(direction(mu_i, 0.0), direction(mu_o, phi));
          error = std::max(error, std::abs(kPi * f - 1.0));
        }
      }
    }
    EXPECT_LT(error, last_error) << rms << " um";  // closer to Lambert as it roughens
    last_error = error;
    const GhsBrdf oil(params({rms, 4.0}, 550.0, true));
    EXPECT_LT(oil.albedo(0.5), last_albedo) << rms << " um";
    last_albedo = oil.albedo(0.5);
  }
  EXPECT_LT(last_error, 0.03);
  EXPECT_LT(last_albedo, 0.002);
}

TEST(GhsBrdf, AlbedoTableMatchesABruteForceGrid) {
  // The tables' ray quadrature against a plain midpoint rule over the hemisphere in θ, φ.
  const GhsBrdf brdf(params({0.3, 1.0}, 550.0));
  for (double mu : {1.0, 0.7, 0.3}) {
    const auto l = direction(mu, 0.0);
    constexpr int kTheta = 300, kPhi = 300;
    double total = 0.0;
    for (int j = 0; j < kTheta; ++j) {
      const double theta = (j + 0.5) * (kPi / 2.0) / kTheta;
      for (int i = 0; i < kPhi; ++i) {
        const double phi = (i + 0.5) * 2.0 * kPi / kPhi;
        total += brdf.eval(l, direction(std::cos(theta), phi)) * std::cos(theta) * std::sin(theta) *
                 (kPi / 2.0 / kTheta) * (2.0 * kPi / kPhi);
      }
    }
    EXPECT_NEAR(brdf.albedo(mu), total, 0.01 * total + 1e-4) << "cos_i " << mu;
  }
}

TEST(GhsBrdf, SmoothLimitIsTheFresnelMirror) {
  for (double wavelength : {420.0, 550.0, 680.0}) {
    const GhsBrdf brdf(params({1e-5, 4.0}, wavelength, true, 2e-3));
    const double n = binder_index(wavelength);
    for (double mu : {1.0, 0.8, 0.5, 0.2}) {
      EXPECT_NEAR(brdf.albedo(mu), fresnel_dielectric(mu, n), 0.01 * fresnel_dielectric(mu, n))
          << wavelength << " nm, cos " << mu;
      // All of it within a few source widths of the mirror direction.
      const auto l = direction(mu, 0.0);
      const double sin_i = std::sqrt(1.0 - mu * mu);
      const double near_mirror = GhsBrdf::integrate_disc(mu, 1e-5, [&](double x, double y) {
        if (std::hypot(x + sin_i, y) > 0.01) return 0.0;
        return brdf.eval(l, {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))});
      });
      EXPECT_NEAR(near_mirror, fresnel_dielectric(mu, n), 0.02 * fresnel_dielectric(mu, n));
    }
  }
}

TEST(GhsBrdf, RougherSpreadsTheSameLightWider) {
  // Head on, the mirror's peak falls and the light at 30° off it rises with the roughness,
  // while the total stays the Fresnel reflectance.
  double last_peak = 1e300, last_wide = 0.0;
  for (double rms : {0.005, 0.02, 0.05, 0.1, 0.3}) {
    const GhsBrdf brdf(params({rms, 4.0}, 550.0));
    const double peak = brdf.eval(direction(1.0, 0.0), direction(1.0, 0.0));
    const double wide = brdf.eval(direction(1.0, 0.0), direction(std::cos(0.5), 0.0));
    EXPECT_LT(peak, last_peak);
    EXPECT_GT(wide, last_wide);
    EXPECT_NEAR(brdf.albedo(1.0), fresnel_dielectric(1.0, binder_index(550.0)), 0.002);
    last_peak = peak;
    last_wide = wide;
  }
}

TEST(GhsBrdf, BlueScattersMoreThanRed) {
  // σ/λ sets the phase variance: a satin surface keeps more of its mirror in red than blue.
  const Roughness satin = finish_roughness(Finish::satin);
  const auto l = direction(std::cos(0.3), 0.0);
  const auto mirror = direction(std::cos(0.3), kPi);
  const GhsBrdf blue(params(satin, 420.0, false)), red(params(satin, 680.0, false));
  EXPECT_GT(red.eval(l, mirror), 1.5 * blue.eval(l, mirror));
}

TEST(GhsBrdf, RoughLimitIsFlatInSlopeSpace) {
  // Very rough (σ ≫ λ, slopes ≫ 1): the GHS kernel tends to geometric optics with a flat
  // slope distribution, kernel ∝ 1 / (cos θ_i + cos θ_o)² (docs/surface.md): Lambert's
  // constant up to that obliquity, no highlight left anywhere.
  GhsParams p = params({20.0, 4.0}, 550.0, false);
  const auto l = direction(std::cos(0.6), 0.0);
  std::vector<double> scaled;
  for (double theta = 0.0; theta < 1.4; theta += 0.2) {
    for (double phi : {0.0, 1.5, kPi}) {
      const auto v = direction(std::cos(theta), phi);
      const double rho = std::hypot(l[0] + v[0], l[1] + v[1]);
      scaled.push_back(ghs_kernel(p, l[2], v[2], rho) * std::pow(l[2] + v[2], 2.0));
    }
  }
  const auto [lo, hi] = std::minmax_element(scaled.begin(), scaled.end());
  EXPECT_LT(*hi / *lo, 1.05);
  // The BRDF keeps all of the light: what the renormalisation's min() and shadowing take from
  // single scattering comes back scattered again.
  const GhsBrdf brdf(p);
  EXPECT_GT(brdf.hemispherical_albedo(), 0.98);
  EXPECT_LE(brdf.hemispherical_albedo(), 1.0 + 3e-3);
}
