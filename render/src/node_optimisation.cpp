// The node search of optimised rules (node_optimisation.hpp); the training paints and the
// readout fit are in node_optimisation_fit.cpp, the cache of built rules in node_cache.cpp.
#include "impasto/render/node_optimisation.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace impasto::render {
namespace {

// --- the node search ---
constexpr int kMinGap = 3;          // grid steps between neighbouring nodes
constexpr int kFirstSweepStep = 2;  // grid steps between the positions the first sweep tries
constexpr int kLocalRadius = 8;     // grid steps a node may move in a later sweep
constexpr int kSearchPaints = 500;  // the search fits every k-th training paint, about this many
constexpr int kMaxSweeps = 8;

}  // namespace

OptimisedRule optimise_nodes(const PaletteTrainingSet& training, const data::Spectrum& light,
                             const data::ColorMatchingFunctions& cmf, int nodes,
                             const WavelengthRange& range) {
  OptimisedRule result;
  result.sampling = make_spectral_sampling(light, cmf, nodes, range, NodeWeights::interpolatory);
  if (nodes == 0) return result;
  result.gauss_training = training.error_of(result.sampling);

  const std::vector<double>& grid = training.grid_nm();
  const int grid_size = training.grid_size();
  const int gap = std::min(kMinGap, std::max(1, (grid_size - 1) / std::max(nodes, 1)));
  // Two starts: the Gaussian nodes, and as many nodes evenly spaced over the same span (the
  // descent can stall where a node has no better place between its neighbours).
  std::vector<double> gauss_at(static_cast<std::size_t>(nodes));
  std::vector<double> even_at(static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i) {
    const auto k = static_cast<std::size_t>(i);
    gauss_at[k] = (result.sampling.wavelengths_nm[k] - grid.front()) / range.step_nm;
  }
  for (int i = 0; i < nodes; ++i) {
    const double share = nodes > 1 ? static_cast<double>(i) / (nodes - 1) : 0.5;
    even_at[static_cast<std::size_t>(i)] =
        gauss_at.front() + share * (gauss_at.back() - gauss_at.front());
  }
  // Grid indices, increasing, at least `gap` apart.
  auto to_positions = [&](const std::vector<double>& at) {
    std::vector<int> position(static_cast<std::size_t>(nodes));
    for (int i = 0; i < nodes; ++i) {
      const auto k = static_cast<std::size_t>(i);
      position[k] = std::clamp(static_cast<int>(std::lround(at[k])), 0, grid_size - 1);
      if (i > 0) position[k] = std::max(position[k], position[k - 1] + gap);
    }
    for (int i = nodes - 1; i >= 0; --i) {
      const auto k = static_cast<std::size_t>(i);
      position[k] = std::min(position[k], i + 1 < nodes ? position[k + 1] - gap : grid_size - 1);
    }
    return position;
  };

  const std::size_t paints = static_cast<std::size_t>(training.paint_count());
  // The node search fits a regular subset of the paints (the held-out error follows the
  // training error closely, so the subset loses little); the final fit uses them all.
  auto fit_at = [&](const std::vector<int>& at, std::size_t stride, int passes) {
    std::vector<double> values;
    values.reserve((paints / stride + 1) * at.size());
    for (std::size_t p = 0; p < paints; p += stride) {
      for (int k : at) values.push_back(training.reflectance_at_grid(k)[p]);
    }
    return training.fit(values, static_cast<int>(at.size()), static_cast<int>(stride), passes);
  };
  const std::size_t stride = std::max<std::size_t>(1, paints / kSearchPaints);
  auto trial = [&](const std::vector<int>& at) { return fit_at(at, stride, kSearchReadoutPasses); };

  // Coordinate descent: each node in turn to its best place between its neighbours (every
  // kFirstSweepStep-th one in the first sweep, then within kLocalRadius), until none moves.
  auto descend = [&](std::vector<int> position) {
    RuleError best_error = trial(position).second;
    ++result.trials;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
      bool moved = false;
      for (int i = 0; i < nodes; ++i) {
        const auto k_i = static_cast<std::size_t>(i);
        const int low = i > 0 ? position[k_i - 1] + gap : 0;
        const int high = i + 1 < nodes ? position[k_i + 1] - gap : grid_size - 1;
        const int here = position[k_i];
        const int first = sweep == 0 ? low : std::max(low, here - kLocalRadius);
        const int last = sweep == 0 ? high : std::min(high, here + kLocalRadius);
        const int step = sweep == 0 ? kFirstSweepStep : 1;
        std::vector<int> candidates;
        for (int k = first; k <= last; k += step) {
          if (k != here) candidates.push_back(k);
        }
        std::vector<std::pair<std::vector<std::array<double, 3>>, RuleError>> outcome(
            candidates.size());
        tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t k) {
          std::vector<int> at = position;
          at[k_i] = candidates[k];
          outcome[k] = trial(at);
        });
        result.trials += static_cast<int>(candidates.size());
        std::size_t chosen = candidates.size();
        double chosen_value = rule_objective(best_error) - 1e-9;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
          if (!outcome[k].first.empty() && rule_objective(outcome[k].second) < chosen_value) {
            chosen = k;
            chosen_value = rule_objective(outcome[k].second);
          }
        }
        if (chosen < candidates.size()) {
          position[k_i] = candidates[chosen];
          best_error = outcome[chosen].second;
          moved = true;
        }
      }
      if (!moved) break;
    }
    return std::pair{position, rule_objective(best_error)};
  };
  const auto from_gauss = descend(to_positions(gauss_at));
  const auto from_even = descend(to_positions(even_at));
  const std::vector<int>& position =
      from_even.second < from_gauss.second ? from_even.first : from_gauss.first;
  std::vector<std::array<double, 3>> best_readout;
  best_readout = fit_at(position, 1, kReadoutPasses).first;
  if (best_readout.empty()) return result;  // no finite fit: keep the Gaussian rule
  SpectralSampling& sampling = result.sampling;
  sampling.white_xyz = {0.0, 0.0, 0.0};
  for (int i = 0; i < nodes; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sampling.wavelengths_nm[k] = static_cast<float>(grid[static_cast<std::size_t>(position[k])]);
    for (std::size_t c = 0; c < 3; ++c) {
      sampling.to_xyz[k][c] = static_cast<float>(best_readout[k][c]);
      sampling.white_xyz[c] += sampling.to_xyz[k][c];
    }
  }
  result.training = training.error_of(sampling);
  return result;
}

}  // namespace impasto::render
