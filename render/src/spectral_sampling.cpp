#include "impasto/render/spectral_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "impasto/render/gaussian_quadrature.hpp"

namespace impasto::render {
namespace {

void normalise_to_white(SpectralSampling& sampling) {
  double white_y = 0.0;
  for (const auto& w : sampling.to_xyz) white_y += w[1];
  if (!(white_y > 0.0) || !std::isfinite(white_y)) {
    throw std::runtime_error("spectral sampling: a white reflector has no luminance under " +
                             std::string("this light (black or invalid light spectrum)"));
  }
  sampling.white_xyz = {0.0, 0.0, 0.0};
  for (auto& w : sampling.to_xyz) {
    for (int c = 0; c < 3; ++c) {
      w[static_cast<std::size_t>(c)] = static_cast<float>(w[static_cast<std::size_t>(c)] / white_y);
      sampling.white_xyz[static_cast<std::size_t>(c)] += w[static_cast<std::size_t>(c)];
    }
  }
}

// ℓ_i(t) = Π_{k≠i} (t − t_k) / (t_i − t_k): the Lagrange basis of the nodes, evaluated in
// product form (no Vandermonde matrix to invert).
double lagrange_basis(const std::vector<double>& nodes, std::size_t i, double t) {
  double value = 1.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (k != i) value *= (t - nodes[k]) / (nodes[i] - nodes[k]);
  }
  return value;
}

}  // namespace

NodeWeights parse_node_weights(std::string_view text) {
  return util::parse_name(kNodeWeightsNames, text, "node weights");
}

SpectralSampling make_spectral_sampling(const data::Spectrum& light,
                                        const data::ColorMatchingFunctions& cmf, int nodes,
                                        const WavelengthRange& range, NodeWeights weights) {
  if (nodes < 0 || nodes > kMaxNodes) {
    throw std::runtime_error("spectral sampling: wavelength count " + std::to_string(nodes) +
                             " is outside 1.." + std::to_string(kMaxNodes) +
                             " (0 for the full spectrum)");
  }
  const std::vector<double> grid =
      data::wavelength_grid(range.first_nm, range.last_nm, range.step_nm);
  std::vector<double> power(grid.size());
  std::vector<double> cmf_sum(grid.size());
  for (std::size_t j = 0; j < grid.size(); ++j) {
    power[j] = light.at(grid[j]);
    if (!std::isfinite(power[j]) || power[j] < 0.0) {
      throw std::runtime_error("spectral sampling: light '" + light.name + "' is negative or " +
                               "not finite at " + std::to_string(grid[j]) + " nm");
    }
    cmf_sum[j] = cmf.x.at(grid[j]) + cmf.y.at(grid[j]) + cmf.z.at(grid[j]);
  }

  SpectralSampling sampling;
  // Grid wavelength j as a node of the full-spectrum weights E x̄ Δλ etc. (times `share`).
  const auto add_grid_node = [&](std::size_t j, double share) {
    const double e = share * power[j] * range.step_nm;
    sampling.wavelengths_nm.push_back(static_cast<float>(grid[j]));
    sampling.to_xyz.push_back({static_cast<float>(e * cmf.x.at(grid[j])),
                               static_cast<float>(e * cmf.y.at(grid[j])),
                               static_cast<float>(e * cmf.z.at(grid[j]))});
  };
  if (nodes == 0) {
    sampling.full_spectrum = true;
    sampling.rule = "the full spectrum";
    for (std::size_t j = 0; j < grid.size(); ++j) add_grid_node(j, 1.0);
    normalise_to_white(sampling);
    return sampling;
  }

  // The measure: W(λ) = E(λ)(x̄ + ȳ + z̄)(λ) times the grid step, one point per grid wavelength.
  std::vector<double> masses(grid.size());
  for (std::size_t j = 0; j < grid.size(); ++j) masses[j] = power[j] * cmf_sum[j] * range.step_nm;
  // A light of no more visible lines than nodes (a laser, three narrow LED lines): its own
  // wavelengths are the exact rule, whatever the weights asked for. The other nodes (the
  // palette and the GPU hold `nodes` of them) go to dark wavelengths spread over the range,
  // with no weight.
  const auto lit = std::count_if(masses.begin(), masses.end(), [](double m) { return m > 0.0; });
  if (lit == 0)
    throw std::runtime_error(
        "spectral sampling: light '" + light.name + "' has no power where the eye sees (" +
        std::to_string(range.first_nm) + "-" + std::to_string(range.last_nm) + " nm)");
  if (lit <= nodes) {
    std::vector<std::size_t> chosen;
    for (std::size_t j = 0; j < grid.size(); ++j)
      if (masses[j] > 0.0) chosen.push_back(j);
    const std::size_t dark = static_cast<std::size_t>(nodes) - chosen.size();
    std::vector<std::size_t> unlit;
    for (std::size_t j = 0; j < grid.size(); ++j)
      if (!(masses[j] > 0.0)) unlit.push_back(j);
    for (std::size_t k = 0; k < dark; ++k)
      chosen.push_back(unlit[(2 * k + 1) * unlit.size() / (2 * dark)]);
    std::sort(chosen.begin(), chosen.end());
    sampling.rule = "the light's own " + std::to_string(lit) + " lines (exact)";
    sampling.light_lines = true;
    for (const std::size_t j : chosen) add_grid_node(j, masses[j] > 0.0 ? 1.0 : 0.0);
    normalise_to_white(sampling);
    return sampling;
  }
  const QuadratureRule rule = gauss_rule(grid, masses, nodes);

  sampling.rule = std::string(util::name_of(kNodeWeightsNames, weights == NodeWeights::impasto
                                                                   ? NodeWeights::impasto
                                                                   : NodeWeights::interpolatory));
  if (weights != NodeWeights::impasto) {  // the palette-trained ones start from it
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      std::array<double, 3> w{0.0, 0.0, 0.0};
      for (std::size_t j = 0; j < grid.size(); ++j) {
        const double e = power[j] * range.step_nm * lagrange_basis(rule.nodes, i, grid[j]);
        w[0] += e * cmf.x.at(grid[j]);
        w[1] += e * cmf.y.at(grid[j]);
        w[2] += e * cmf.z.at(grid[j]);
      }
      sampling.wavelengths_nm.push_back(static_cast<float>(rule.nodes[i]));
      sampling.to_xyz.push_back(
          {static_cast<float>(w[0]), static_cast<float>(w[1]), static_cast<float>(w[2])});
    }
    normalise_to_white(sampling);
    return sampling;
  }
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double nm = rule.nodes[i];
    const double x = cmf.x.at(nm);
    const double y = cmf.y.at(nm);
    const double z = cmf.z.at(nm);
    const double sum = x + y + z;
    const double w = sum > 0.0 ? rule.weights[i] / sum : 0.0;
    sampling.wavelengths_nm.push_back(static_cast<float>(nm));
    sampling.to_xyz.push_back(
        {static_cast<float>(w * x), static_cast<float>(w * y), static_cast<float>(w * z)});
  }
  normalise_to_white(sampling);
  return sampling;
}

std::vector<float> sample_at_nodes(const data::Spectrum& spectrum,
                                   const SpectralSampling& sampling) {
  std::vector<float> values(sampling.wavelengths_nm.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = static_cast<float>(spectrum.at(sampling.wavelengths_nm[i]));
  }
  return values;
}

std::array<double, 3> reflectance_to_xyz(const SpectralSampling& sampling,
                                         const float* reflectance) {
  std::array<double, 3> xyz{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < sampling.to_xyz.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) xyz[c] += sampling.to_xyz[i][c] * reflectance[i];
  }
  return xyz;
}

std::string describe_rule(const SpectralSampling& sampling) {
  std::string text = sampling.rule;
  if (!sampling.full_spectrum) text += ", " + std::to_string(sampling.size()) + " wavelengths";
  if (sampling.estimated_mean_de00 >= 0.0) {
    char estimate[96];
    std::snprintf(estimate, sizeof estimate,
                  ": %.2f mean, %.2f max dE00 on the palette's training paints",
                  sampling.estimated_mean_de00, sampling.estimated_max_de00);
    text += estimate;
  }
  return text;
}

}  // namespace impasto::render
