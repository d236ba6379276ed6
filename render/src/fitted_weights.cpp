#include "impasto/render/fitted_weights.hpp"

#include <Eigen/Dense>

#include <cmath>

#include "impasto/render/kubelka_munk.hpp"

namespace impasto::render {
namespace {

constexpr double kRidge = 1e-3;  // ridge strength, relative to the mean diagonal of AᵀWA

// One training paint: pigment concentrations, thickness (mm), ground (true: `ground`).
struct TrainingPaint {
  std::vector<std::pair<std::size_t, float>> mix;
  float thickness_mm;
  bool over_ground;
};

std::vector<TrainingPaint> training_paints(const std::vector<data::Pigment>& pigments) {
  std::vector<TrainingPaint> paints;
  std::size_t white = pigments.size();
  for (std::size_t p = 0; p < pigments.size(); ++p) {
    if (pigments[p].name == "Titanium White") white = p;
  }
  for (std::size_t p = 0; p < pigments.size(); ++p) {
    paints.push_back({{{p, 1.0f}}, 2.0f, true});
    for (float glaze : {0.005f, 0.03f}) {
      paints.push_back({{{p, 1.0f}}, glaze, true});
      paints.push_back({{{p, 1.0f}}, glaze, false});
    }
    if (white < pigments.size() && p != white) {
      for (float share : {0.25f, 1.0f / 21.0f}) {
        paints.push_back({{{p, share}, {white, 1.0f - share}}, 2.0f, true});
      }
    }
    for (std::size_t q = p + 1; q < pigments.size(); ++q) {
      for (float share : {0.25f, 0.75f}) {
        paints.push_back({{{p, share}, {q, 1.0f - share}}, 2.0f, true});
      }
    }
  }
  return paints;
}

// Reflectance of a paint at the given wavelengths.
void paint_reflectance(const TrainingPaint& paint, const std::vector<data::Pigment>& pigments,
                       const data::Spectrum& ground, double thickness_scale_mm,
                       const std::vector<float>& wavelengths, std::vector<float>& out) {
  out.resize(wavelengths.size());
  const auto thickness = static_cast<float>(paint.thickness_mm / thickness_scale_mm);
  for (std::size_t i = 0; i < wavelengths.size(); ++i) {
    const double nm = wavelengths[i];
    float absorption = 0.0f, scattering = 0.0f;
    for (const auto& [pigment, share] : paint.mix) {
      km::accumulate_pigment(share, static_cast<float>(pigments[pigment].K.at(nm)),
                             static_cast<float>(pigments[pigment].S.at(nm)), absorption,
                             scattering);
    }
    const float below = paint.over_ground ? static_cast<float>(ground.at(nm)) : 0.0f;
    out[i] = km::composite(km::layer(absorption, scattering, thickness), below);
  }
}

}  // namespace

void fit_node_weights(SpectralSampling& sampling, const data::Spectrum& light,
                      const data::ColorMatchingFunctions& cmf, const WavelengthRange& range,
                      const std::vector<data::Pigment>& pigments, const data::Spectrum& ground,
                      double thickness_scale_mm) {
  if (pigments.empty() || sampling.full_spectrum) return;
  const SpectralSampling reference = make_spectral_sampling(light, cmf, 0, range);
  const std::vector<TrainingPaint> paints = training_paints(pigments);
  const auto n = static_cast<Eigen::Index>(sampling.size());
  const auto rows = static_cast<Eigen::Index>(paints.size()) + 1;  // + the perfect white

  Eigen::MatrixXd a(rows, n);
  Eigen::MatrixXd b(rows, 3);
  Eigen::VectorXd row_weight(rows);
  std::vector<float> full, at_nodes;
  for (Eigen::Index r = 0; r + 1 < rows; ++r) {
    const TrainingPaint& paint = paints[static_cast<std::size_t>(r)];
    paint_reflectance(paint, pigments, ground, thickness_scale_mm, reference.wavelengths_nm, full);
    paint_reflectance(paint, pigments, ground, thickness_scale_mm, sampling.wavelengths_nm,
                      at_nodes);
    const auto xyz = reflectance_to_xyz(reference, full.data());
    for (Eigen::Index i = 0; i < n; ++i) a(r, i) = at_nodes[static_cast<std::size_t>(i)];
    for (Eigen::Index c = 0; c < 3; ++c) b(r, c) = xyz[static_cast<std::size_t>(c)];
    row_weight[r] = 1.0 / (xyz[1] + 0.05);
  }
  // A perfect white reflector must stay exact: the display's white depends on it.
  a.row(rows - 1).setOnes();
  for (Eigen::Index c = 0; c < 3; ++c)
    b(rows - 1, c) = reference.white_xyz[static_cast<std::size_t>(c)];
  row_weight[rows - 1] = 1e4 * static_cast<double>(rows);

  // Ridge toward the interpolatory weights: (AᵀWA + λI) t = AᵀWb + λ t₀.
  const Eigen::MatrixXd weighted_a = row_weight.asDiagonal() * a;
  const Eigen::MatrixXd normal = a.transpose() * weighted_a;
  // λ relative to the paints' part of AᵀWA (the white row's weight would swamp it).
  const Eigen::MatrixXd paints_only =
      a.topRows(rows - 1).transpose() * weighted_a.topRows(rows - 1);
  const double lambda = kRidge * paints_only.trace() / static_cast<double>(n);
  Eigen::MatrixXd prior(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      prior(i, c) = sampling.to_xyz[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
    }
  }
  const Eigen::MatrixXd lhs = normal + lambda * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd rhs = weighted_a.transpose() * b + lambda * prior;
  const Eigen::MatrixXd fitted = lhs.ldlt().solve(rhs);

  sampling.white_xyz = {0.0, 0.0, 0.0};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto w = static_cast<float>(fitted(i, c));
      if (!std::isfinite(w)) return;  // keep the interpolatory weights
      sampling.to_xyz[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] = w;
    }
  }
  for (const auto& w : sampling.to_xyz) {
    for (std::size_t c = 0; c < 3; ++c) sampling.white_xyz[c] += w[c];
  }
}

}  // namespace impasto::render
