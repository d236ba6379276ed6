#pragma once
// The wavelengths a painting is rendered at for one light, and how reflectance sampled at
// them becomes CIE XYZ (IMPaSTo §5.4).
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/data/spectrum.hpp"
#include "impasto/util/enum_names.hpp"

namespace impasto::render {

// Most nodes a Gaussian rule may have (one cell stores one float or half per node).
inline constexpr int kMaxNodes = 16;

// The wavelength interval (nm) and grid step of the measure the rules integrate against:
// where the bundled pigment data exist, so nothing outside it is extrapolated.
struct WavelengthRange {
  double first_nm = 360.0;
  double last_nm = 750.0;
  double step_nm = 1.0;
};

// How the per-node XYZ weights are made from the Gaussian rule for W = E·(x̄ + ȳ + z̄).
enum class NodeWeights {
  // IMPaSTo §5.4: w_i · x̄/(x̄+ȳ+z̄)(λ_i), and likewise for ȳ, z̄. Exact for the sum X+Y+Z
  // of polynomials up to degree 2N−1, but each channel carries the error of treating
  // x̄/(x̄+ȳ+z̄) as a polynomial (a white is off by up to a few per cent in X and Z).
  impasto,
  // Interpolatory: per channel, Σ_j E x̄ ℓ_i(λ_j) over the grid with ℓ_i the Lagrange
  // polynomial of the nodes: the reflectance is interpolated by a degree N−1 polynomial
  // through the nodes and that is integrated exactly. Same nodes; the three rules still sum
  // to the Gaussian one; a white (any constant) comes out exact.
  interpolatory,
  // The Gaussian nodes with the readout refitted to the palette's own paints (see
  // node_optimisation.hpp): weighted least squares in CIELAB on mixes, tints and glazes of
  // the pigments, so the nodes' values predict XYZ of real paint spectra.
  fitted,
  // Nodes moved from the Gaussian ones and the readout refitted, both to the palette's
  // paints under this light (node_optimisation.hpp). Still N nodes per cell.
  optimised,
};

// Their spellings (--weights).
inline constexpr util::EnumNames<NodeWeights, 4> kNodeWeightsNames{
    {{NodeWeights::impasto, "impasto"},
     {NodeWeights::interpolatory, "interpolatory"},
     {NodeWeights::fitted, "fitted"},
     {NodeWeights::optimised, "optimised"}}};

// One of kNodeWeightsNames; throws std::runtime_error naming the accepted values.
NodeWeights parse_node_weights(std::string_view text);

// X, Y, Z = Σ_i to_xyz[i] · R(wavelengths_nm[i]) for a reflectance spectrum R.
struct SpectralSampling {
  std::vector<float> wavelengths_nm;
  std::vector<std::array<float, 3>> to_xyz;  // per node, scaled so a perfect white has Y = 1
  std::array<double, 3> white_xyz{};         // XYZ of a perfect white reflector: Σ_i to_xyz[i]
  bool full_spectrum = false;                // every grid wavelength rather than a rule
  bool light_lines = false;  // the light's own few lines: exact, no trained rule does better
  // How the wavelengths and weights were chosen, for the user ("optimised", "interpolatory:
  // the palette has too few paints to train the optimised rule", ...); not part of the rule.
  std::string rule;
  // A trained rule's error on its palette's training paints (masstones, tints, glazes, pairs;
  // node_optimisation.hpp): mean and max CIEDE2000 against the 1 nm spectrum. The estimate a
  // user sees of what the rule costs in colour; negative when unknown (an untrained rule).
  double estimated_mean_de00 = -1.0, estimated_max_de00 = -1.0;

  int size() const { return static_cast<int>(wavelengths_nm.size()); }
};

// The rule in words for a user: "optimised, 8 wavelengths: 0.36 mean, 2.03 max dE00 on the
// palette's training paints" (the estimate when known).
std::string describe_rule(const SpectralSampling& sampling);

// The sampling for `light` (relative spectral power) seen through `cmf`:
//   nodes > 0:  the nodes-point Gaussian rule for W(λ) = E(λ)(x̄ + ȳ + z̄)(λ) on the grid of
//               `range`, with per-node XYZ weights as `weights` says (fitted and optimised
//               need the palette: make_palette_sampling; here they are interpolatory);
//   nodes == 0: every grid wavelength with weights E x̄ Δλ etc. (the full-spectrum reference).
// Normalised so that a perfect white reflector gives Y = 1 under this very sampling.
// Throws std::runtime_error when nodes is outside 0..kMaxNodes or the light is black or
// not finite over the range.
SpectralSampling make_spectral_sampling(const data::Spectrum& light,
                                        const data::ColorMatchingFunctions& cmf, int nodes,
                                        const WavelengthRange& range = {},
                                        NodeWeights weights = NodeWeights::interpolatory);

// A spectrum sampled at the sampling's wavelengths (linear interpolation).
std::vector<float> sample_at_nodes(const data::Spectrum& spectrum,
                                   const SpectralSampling& sampling);

// XYZ of the reflectance values at the nodes (reflectance.size() == sampling.size()).
std::array<double, 3> reflectance_to_xyz(const SpectralSampling& sampling,
                                         const float* reflectance);

}  // namespace impasto::render
