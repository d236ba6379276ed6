#pragma once
// The light a paint (or varnish) surface reflects before any enters the paint: a rough
// dielectric interface after the generalised Harvey–Shack (GHS) scalar diffraction theory
// (Krywonos, Harvey & Choi 2011, JOSA A 28(6):1121; used for rendering by Vyatkin &
// Dolgovesov 2022, Eq. 4, the seed of docs/surface.md), for a Gaussian height distribution of
// RMS roughness σ and a Gaussian autocorrelation of correlation length ℓ, at one wavelength,
// with the exact Fresnel reflectance of the binder. The CPU reference: plain double code;
// the renderer reads it through surface_shading.hpp. Derivation and figures: docs/surface.md.
//
// Directions point away from the surface (toward the light, toward the viewer) and are
// given by their cosine with the normal and the tangential part of their sum, which is all
// an isotropic surface needs.
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "impasto/flakes/fresnel.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/util/enum_names.hpp"

namespace impasto::render::surface {

// Micro-roughness of a surface: RMS height and correlation length, micrometres.
struct Roughness {
  double rms_um = 0.0;
  double correlation_um = 1.0;
};

// Refractive index of an oil or resin film at a wavelength: n_d at the sodium line
// (589.3 nm) and a Cauchy term, B = 0.0042 µm² (linseed oil and natural resins have Abbe
// numbers near 50: n_F − n_C ≈ 0.01).
double binder_index(double wavelength_nm, double n_d = 1.48);

// Unpolarised Fresnel reflectance of light meeting a dielectric of index n (from air) at an
// incidence cosine cos_i: the one formula, flakes/fresnel.hpp.
using flakes::fresnel_dielectric;

// One wavelength of a rough surface's reflection.
struct GhsParams {
  Roughness roughness;
  double wavelength_nm = 550.0;
  double index = 1.48;  // of the film (the medium above it is air)
  // The light's angular spread as a Gaussian in direction cosines (standard deviation per
  // axis): a disc of angular radius a has a/2. Keeps the mirror of a smooth surface finite.
  double source_sigma = 0.013;
  bool fresnel = true;  // false: a perfect reflector (F = 1), for the white-furnace test
  // Slopes finer than the height grid resolves (bristle marks, pigment grain under the
  // 0.1 mm cells), RMS in radians: each term's spread grows by ((cos θ_i + cos θ_o) s)², as a
  // facet tilted by δ turns the reflection by that much δ in direction cosines.
  double subcell_slope_rms = 0.0;
};

// Smith's shadowing–masking function G₁ = 1 / (1 + Λ) of a Gaussian (Beckmann) surface of
// RMS slope `slope_rms` per axis, for a direction at cos θ: 1 head on, 0 at grazing.
double smith_shadowing(double cos_theta, double slope_rms);

// The scatter kernel before Fresnel and renormalisation, in direction-cosine space: the
// Poisson mixture Σ_m e^(−g) g^m/m! N(ρ; s_m² + source² + sub-cell slopes), with
//   g   = (2πσ/λ)² (cos θ_i + cos θ_o)²        (the GHS phase variance)
//   s_m² = m / (2π² (ℓ/λ)²)                     (the FT of the m-th power of the ACV)
//   ρ   = |t_i + t_o|, t the tangential part of each unit direction (0 at the mirror).
// Its integral over the whole direction-cosine plane is 1 (the m = 0 term is the mirror).
double ghs_kernel(const GhsParams& p, double cos_i, double cos_o, double rho);

// The BRDF of one wavelength, with its energy renormalisation tabulated once:
//   f(ω_i, ω_o) = F(ω_i·h) · min(r(θ_i), r(θ_o)) · G(θ_i) G(θ_o) · ghs_kernel(...)
//               + q(θ_i) q(θ_o)
// where r(θ) = 1 / ∫_disc kernel: the share the GHS loses to evanescent directions
// (α² + β² > 1) is handed back (Krywonos' renormalisation), symmetrised by the min so that
// f stays reciprocal. G is Smith's shadowing–masking of the surface's Gaussian slopes (its
// own and the sub-cell ones): light a facet sends into a neighbouring facet. What single
// scattering does not return (1 − E₁, E₁ its albedo with F = 1) is scattered again; after
// its second bounce its direction is random, a reciprocal diffuse lobe
//   q(θ_i) q(θ_o) = F_ms (1 − E₁(θ_i)) (1 − E₁(θ_o)) / (π (1 − Ē₁)),
//   F_ms = F̄² Ē₁ / (1 − F̄ (1 − Ē₁))      (F̄ the hemispherical Fresnel: each bounce
//                                          reflects F̄, the rest enters the paint)
// after Kulla & Conty (2017). With F = 1 it conserves the light exactly (white furnace), and
// as the slopes grow G → 0 and f → 1/π: Lambert. h is the half vector.
class GhsBrdf {
 public:
  static constexpr int kTableSize = 33;  // incidence cosines 0..1

  explicit GhsBrdf(const GhsParams& params);

  const GhsParams& params() const { return params_; }
  // f (1/sr) for light from cos_i, seen from cos_o, with |t_i + t_o| = rho and the cosine of
  // the angle between either direction and the half vector (the Fresnel angle).
  double eval(double cos_i, double cos_o, double rho, double cos_half) const;
  // The same from two unit vectors in the surface's frame (z = normal).
  double eval(const std::array<double, 3>& to_light, const std::array<double, 3>& to_viewer) const;
  // Directional albedo: ∫ f cos θ_o dω_o for light from cos_i (tabulated, interpolated).
  double albedo(double cos_i) const;
  // Hemispherical albedo under uniform light: 2 ∫ albedo(μ) μ dμ.
  double hemispherical_albedo() const { return hemispherical_albedo_; }
  // The renormalisation r(θ) (mostly >= 1), interpolated.
  double renormalisation(double cos_i) const;
  // Smith's shadowing–masking G(θ) of the surface's slopes, interpolated (1 head on).
  double shadowing(double cos_i) const;
  // The multiply scattered lobe's factor q(θ) (f_ms = q(θ_i) q(θ_o)), interpolated.
  double multiple(double cos_i) const;
  // The RMS slope (radians, per axis) of the surface: √2 σ/ℓ of its Gaussian heights and the
  // sub-cell slopes.
  double slope_rms() const;

  // Numerical ∫_disc of integrand(t_o) dα dβ around the mirror point of incidence cos_i:
  // log-spaced rings about the lobe centre, clipped to the unit disc (the tables and tests).
  template <typename F>
  static double integrate_disc(double cos_i, double inner_radius, const F& integrand);

 private:
  double table_lookup(const std::array<double, kTableSize>& table, double cos_i) const;
  // The first bounce alone: F (or 1) · min(r_i, r_o) · G_i G_o · kernel.
  double single_scattering(double cos_i, double cos_o, double rho, double cos_half,
                           bool fresnel) const;
  GhsParams params_;
  std::array<double, kTableSize> renormalisation_{};
  std::array<double, kTableSize> albedo_{};
  std::array<double, kTableSize> shadowing_{};
  std::array<double, kTableSize> multiple_{};
  double hemispherical_albedo_ = 0.0;
};

// The kinds of medium and varnish an artist chooses between (part of the paint:
// paintcore/paint_surface.hpp), and their surfaces.
using Finish = paintcore::Finish;
inline constexpr util::EnumNames<Finish, 3> kFinishNames{
    {{Finish::gloss, paintcore::finish_name(Finish::gloss)},
     {Finish::satin, paintcore::finish_name(Finish::satin)},
     {Finish::matte, paintcore::finish_name(Finish::matte)}}};
// RMS roughness and correlation length of a film of that finish (paintcore's table).
Roughness finish_roughness(Finish finish);
// A surface between the finishes by its log10 RMS (paintcore::roughness_at_log_rms).
Roughness roughness_at_log_rms(double log_rms);

template <typename F>
double GhsBrdf::integrate_disc(double cos_i, double inner_radius, const F& integrand) {
  // Rays from the lobe centre c = −t_i (t_i along +x) to where each leaves the unit disc,
  // so the disc's edge is exact: log-spaced out to half way (narrow lobes), then in
  // q = sqrt(1 − ρ/edge)-like steps that follow cos θ_o's square root at the edge. The half
  // plane y >= 0, doubled (isotropy); the small disc inside inner_radius by its centre value.
  constexpr int kLogSteps = 32;
  constexpr int kEdgeSteps = 24;
  constexpr int kAngles = 48;
  constexpr double kPi = 3.14159265358979323846;
  const double sin_i = std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
  const double cx = -sin_i;
  double total = integrand(cx, 0.0) * kPi * inner_radius * inner_radius * (sin_i < 1.0 ? 1.0 : 0.5);
  const double dphi = kPi / kAngles;
  for (int j = 0; j < kAngles; ++j) {
    const double phi = (j + 0.5) * dphi;
    const double ux = std::cos(phi), uy = std::sin(phi);
    const double along = cx * ux;  // c·u
    const double edge = -along + std::sqrt(std::max(0.0, along * along - cx * cx + 1.0));
    if (edge <= inner_radius) continue;
    const double middle = std::max(inner_radius, 0.5 * edge);
    // ρ dρ dφ, doubled for the lower half plane.
    const auto add = [&](double rho, double drho) {
      total += 2.0 * integrand(cx + rho * ux, rho * uy) * rho * drho * dphi;
    };
    const double log_step = std::log(middle / inner_radius) / kLogSteps;
    for (int k = 0; k < kLogSteps && log_step > 0.0; ++k) {
      const double rho = inner_radius * std::exp((k + 0.5) * log_step);
      add(rho, rho * log_step);
    }
    const double span = edge - middle;  // ρ = edge − span·q², q in [0, 1]
    for (int k = 0; k < kEdgeSteps; ++k) {
      const double q = (k + 0.5) / kEdgeSteps;
      add(edge - span * q * q, 2.0 * span * q / kEdgeSteps);
    }
  }
  return total;
}

}  // namespace impasto::render::surface
