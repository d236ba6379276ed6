#pragma once
// Brute-force references for the surface models (docs/surface.md), slow and written to check
// the fast ones: never on the rendering path. For `impasto bench surface` and the tests.
//
// 1. Wave optics of a rough surface by Monte Carlo: Gaussian random height fields of RMS σ
//    and Gaussian autocorrelation of length ℓ (white noise filtered in Fourier space), the
//    scalar reflected field of the seed's Eq. 5 under a Gaussian coherence window, by FFT,
//    |field|² averaged over realisations: the scatter kernel ghs_kernel models, without its
//    Poisson series.
// 2. A random walk of light in a paint layer: isotropic scattering (σ_s'), absorption (σ_a),
//    a Fresnel boundary of index η on top and a Lambertian ground below: where the light
//    that enters at one point comes out.
#include <cstdint>
#include <vector>

#include "impasto/render/dipole.hpp"
#include "impasto/render/surface_brdf.hpp"

namespace impasto::render::surface_reference {

// The kernel as a function of ρ = |t_i + t_o| (bins of width rho_step from 0), for phase
// factor γ_i + γ_o = gamma_sum, averaged over `realisations` surfaces. The coherence window
// is chosen so that its angular spread equals params.source_sigma (so the result compares
// with ghs_kernel for those params).
struct KernelProfile {
  double rho_step = 0.0;
  std::vector<double> kernel;  // per bin, in 1/(direction-cosine area), as ghs_kernel
};
KernelProfile wave_optics_kernel(const surface::GhsParams& params, double gamma_sum,
                                 int realisations, std::uint64_t seed);

// Where light entering a layer at the origin leaves it again (per photon that comes out).
struct LayerWalk {
  double reflectance = 0.0;   // share of the entering light that leaves through the top
  double beyond_share = 0.0;  // share of that light leaving beyond `radius_mm`
  double mean_exit_radius_mm = 0.0;
};
LayerWalk random_walk_layer(const dipole::Medium& medium, double thickness_mm, double ground_albedo,
                            double radius_mm, int photons, std::uint64_t seed);

}  // namespace impasto::render::surface_reference
