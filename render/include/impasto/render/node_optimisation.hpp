#pragma once
// Wavelength nodes and per-node XYZ weights chosen for one palette under one light.
//
// A Gaussian rule is optimal for polynomials; K-M reflectances of a real palette are not
// polynomials (steep absorption edges), but they are few and correlated. So the rule is
// trained on paints of the palette: a set of mixes, tints and glazes (training_paints) is
// rendered at every grid nanometre, and
//   - the readout (N × 3 weights from node reflectance to XYZ) is a weighted least-squares
//     fit in linearised CIELAB, reweighted toward CIEDE2000 and toward the worst paints,
//     with a perfect white held exact (fit_readout);
//   - the node wavelengths (whole nanometres of the grid) move by coordinate descent from
//     the Gaussian nodes, each trial refitting the readout, to lower the training paints'
//     mean + max ΔE00.
// The per-cell cost is unchanged: N nodes, N × 3 weights. The training paints are distinct
// from the samples of `impasto bench color` (other ratios, tint strengths, glaze thicknesses
// and a black of zero reflectance), so the bench measures held-out error.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

// One training paint: a single K-M layer of a pigment mix over the ground or over black.
struct TrainingPaint {
  std::vector<std::pair<int, float>> mix;  // palette index, concentration (sums to 1)
  float optical_thickness = 0.0f;          // K-M units (mm / thickness scale)
  bool over_black = false;                 // zero reflectance beneath; else the ground
};

// Every pigment at 0.03 and 0.4 optical units over the ground and over black; tints of 35 %
// and 3 % pigment in White (when the palette has it); every pair at 20/80 and 80/20
// (opaque); every pair at 60/40 as a glaze of 0.5 units over the ground. No opaque layer of
// a single pigment: that is R∞ at any thickness, the very masstone the bench measures.
std::vector<TrainingPaint> training_paints(const std::vector<data::Pigment>& pigments);

// Mean and maximum CIEDE2000 of a set of paints against the 1-nm reference.
struct RuleError {
  double mean_de00 = 0.0;
  double max_de00 = 0.0;
  double tail_de00 = 0.0;  // mean of the worst 1 %
};

// What a readout fit and the node search minimise: mean + 0.2 × the worst 1 %. The goal is
// mean < 0.3 and max < 1.5, so the worst paints weigh a fifth of the mean; the worst 1 %
// stands in for the maximum as it changes more smoothly when a node moves.
double rule_objective(const RuleError& error);

// Reweighting passes of a final readout fit, and of each trial fit of the node search.
inline constexpr int kReadoutPasses = 5;
inline constexpr int kSearchReadoutPasses = 3;

// The training paints of a palette rendered at every grid wavelength, with their reference
// XYZ and CIELAB under one light: everything a rule is fitted and judged against.
class PaletteTrainingSet {
 public:
  // Throws std::runtime_error when the light is black or not finite over the range, or a
  // pigment's K or S is negative or not finite there.
  PaletteTrainingSet(const data::Spectrum& light, const data::ColorMatchingFunctions& cmf,
                     const WavelengthRange& range, const std::vector<data::Pigment>& pigments,
                     const data::Spectrum& ground);

  int paint_count() const { return static_cast<int>(target_xyz_.size()); }
  int grid_size() const { return static_cast<int>(grid_nm_.size()); }
  const std::vector<double>& grid_nm() const { return grid_nm_; }
  // XYZ of a perfect white under the 1-nm reference (Y = 1).
  const std::array<double, 3>& white_xyz() const { return white_xyz_; }

  // ΔE00 of the training paints rendered with `sampling` (its nodes anywhere in the range;
  // K and S interpolated there as the renderer does).
  RuleError error_of(const SpectralSampling& sampling) const;
  // Refits sampling.to_xyz (and white_xyz) to the training paints at its nodes.
  void fit_readout(SpectralSampling& sampling) const;

  // Reflectance of every paint at grid wavelength `index` (paint_count() values).
  const float* reflectance_at_grid(int index) const {
    return &reflectance_[static_cast<std::size_t>(index) * target_xyz_.size()];
  }
  // Fits the readout to every `stride`-th paint (0, stride, 2·stride, …) from their node
  // reflectances, paint-major (one row of `nodes` values per fitted paint), with `passes`
  // reweightings; returns the weights (empty if no fit was finite) and the error they leave
  // on those paints.
  std::pair<std::vector<std::array<double, 3>>, RuleError> fit(
      const std::vector<double>& node_reflectance, int nodes, int stride, int passes) const;

 private:
  std::vector<float> reflectance_at(const std::vector<float>& wavelengths_nm) const;

  std::vector<double> grid_nm_;
  std::vector<data::Pigment> pigments_;
  data::Spectrum ground_;
  std::vector<TrainingPaint> paints_;
  std::vector<float> reflectance_;  // wavelength-major: grid_size() rows of paint_count()
  std::vector<std::array<double, 3>> target_xyz_;
  std::vector<std::array<double, 3>> target_lab_;
  std::vector<std::array<double, 6>> lab_metric_;  // JᵀJ of XYZ → Lab, upper triangle
  std::array<double, 3> white_xyz_{};
};

// What node optimisation found, with the Gaussian rule's error on the same paints.
struct OptimisedRule {
  SpectralSampling sampling;
  RuleError training;        // the optimised rule on the training paints
  RuleError gauss_training;  // the Gaussian rule with interpolatory weights on them
  int trials = 0;            // readout fits tried
};

// Optimises `nodes` wavelengths (1..kMaxNodes) and their weights for the palette under
// `light` from the Gaussian rule. Deterministic (independent of the thread count).
OptimisedRule optimise_nodes(const PaletteTrainingSet& training, const data::Spectrum& light,
                             const data::ColorMatchingFunctions& cmf, int nodes,
                             const WavelengthRange& range);

// The sampling a renderer uses for `weights`: the Gaussian rule (impasto, interpolatory),
// the Gaussian nodes with a readout fitted to the palette (fitted), or optimised nodes and
// readout (optimised). The palette-dependent ones are built once per content (light,
// observer, range, nodes, pigments, ground) and kept in memory and on disk (node_cache.hpp),
// so a light seen before costs a small file read, or nothing, to return to.
SpectralSampling make_palette_sampling(const data::Spectrum& light,
                                       const data::ColorMatchingFunctions& cmf, int nodes,
                                       const WavelengthRange& range, NodeWeights weights,
                                       const std::vector<data::Pigment>& pigments,
                                       const data::Spectrum& ground);

}  // namespace impasto::render
