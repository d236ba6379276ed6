// The training paints of a palette and the readout fitted to them (node_optimisation.hpp);
// the node search that uses them is in node_optimisation.cpp.
#include "impasto/render/node_optimisation.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "impasto/data/colorimetry.hpp"
#include "impasto/render/kubelka_munk_cell.hpp"

namespace impasto::render {
namespace {

// --- the training paints (optical thickness in K-M units) ---
constexpr float kOpaque = 400.0f;  // hides any ground of this palette completely
constexpr float kThinGlaze = 0.03f;
constexpr float kGlaze = 0.4f;
constexpr float kPairGlaze = 0.5f;
constexpr float kStrongTint = 0.35f;  // pigment share in white
constexpr float kPaleTint = 0.03f;
constexpr float kPairShare = 0.2f;       // opaque pairs at 20/80 and 80/20
constexpr float kPairGlazeShare = 0.6f;  // glazed pairs at 60/40

// --- the readout fit ---
constexpr double kMinMaxExponent = 2;  // weight ∝ ΔE^kMinMaxExponent: pulls down the worst
constexpr double kTailShare = 0.2;     // see rule_objective()
constexpr double kTailFraction = 0.01;
constexpr double kErrorFloor = 0.05;  // ΔE00 below which a paint's weight stops shrinking
constexpr double kRidge = 1e-9;       // relative to the mean diagonal: conditioning only

double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// d f(t) / dt for the CIELAB companding function.
double lab_f_slope(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? 1.0 / (3.0 * std::cbrt(t) * std::cbrt(t))
                                   : 1.0 / (3.0 * delta * delta);
}

std::array<double, 3> to_lab(const std::array<double, 3>& xyz, const std::array<double, 3>& white) {
  const double fx = lab_f(xyz[0] / white[0]);
  const double fy = lab_f(xyz[1] / white[1]);
  const double fz = lab_f(xyz[2] / white[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double de00(const std::array<double, 3>& first, const std::array<double, 3>& second) {
  return data::ciede2000({first[0], first[1], first[2]}, {second[0], second[1], second[2]});
}

// JᵀJ of the Jacobian J = ∂(L*, a*, b*)/∂(X, Y, Z) at xyz, upper triangle
// (00, 01, 02, 11, 12, 22): |J e|² is the CIELAB distance of a small XYZ error e.
std::array<double, 6> lab_metric(const std::array<double, 3>& xyz,
                                 const std::array<double, 3>& white) {
  const double gx = lab_f_slope(xyz[0] / white[0]) / white[0];
  const double gy = lab_f_slope(xyz[1] / white[1]) / white[1];
  const double gz = lab_f_slope(xyz[2] / white[2]) / white[2];
  constexpr double l = 116.0, a = 500.0, b = 200.0;
  return {a * a * gx * gx,  -a * a * gx * gy, 0.0, (l * l + a * a + b * b) * gy * gy,
          -b * b * gy * gz, b * b * gz * gz};
}

// Mean of the worst kTailFraction of the errors (at least one).
double tail_mean(std::vector<double> errors) {
  const auto count = std::max<std::size_t>(
      1, static_cast<std::size_t>(kTailFraction * static_cast<double>(errors.size())));
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(count - 1),
                   errors.end(), std::greater<>());
  double sum = 0.0;
  for (std::size_t k = 0; k < count; ++k) sum += errors[k];
  return sum / static_cast<double>(count);
}

constexpr int kPair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};

int index_of(const std::vector<data::Pigment>& pigments, const std::string& name) {
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    if (pigments[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

// The wavelength grid the rules are chosen on, checked against the light.
std::vector<double> checked_grid(const data::Spectrum& light, const WavelengthRange& range) {
  std::vector<double> grid = data::wavelength_grid(range.first_nm, range.last_nm, range.step_nm);
  for (double nm : grid) {
    const double power = light.at(nm);
    if (!std::isfinite(power) || power < 0.0) {
      throw std::runtime_error("node optimisation: light '" + light.name +
                               "' is negative or not finite at " + std::to_string(nm) + " nm");
    }
  }
  return grid;
}

}  // namespace

double rule_objective(const RuleError& error) {
  return error.mean_de00 + kTailShare * error.tail_de00;
}

std::vector<TrainingPaint> training_paints(const std::vector<data::Pigment>& pigments) {
  std::vector<TrainingPaint> paints;
  const int count = static_cast<int>(pigments.size());
  const int white = index_of(pigments, "White");
  for (int p = 0; p < count; ++p) {
    // No opaque layer of one pigment: it is R∞ at any thickness, that is a bench masstone.
    for (float glaze : {kThinGlaze, kGlaze}) {
      paints.push_back({{{p, 1.0f}}, glaze, false});
      paints.push_back({{{p, 1.0f}}, glaze, true});
    }
    if (white >= 0 && p != white) {
      for (float share : {kStrongTint, kPaleTint}) {
        paints.push_back({{{p, share}, {white, 1.0f - share}}, kOpaque, false});
      }
    }
  }
  for (int p = 0; p < count; ++p) {
    for (int q = p + 1; q < count; ++q) {
      for (float share : {kPairShare, 1.0f - kPairShare}) {
        paints.push_back({{{p, share}, {q, 1.0f - share}}, kOpaque, false});
      }
      paints.push_back({{{p, kPairGlazeShare}, {q, 1.0f - kPairGlazeShare}}, kPairGlaze, false});
    }
  }
  return paints;
}

PaletteTrainingSet::PaletteTrainingSet(const data::Spectrum& light,
                                       const data::ColorMatchingFunctions& cmf,
                                       const WavelengthRange& range,
                                       const std::vector<data::Pigment>& pigments,
                                       const data::Spectrum& ground)
    : grid_nm_(checked_grid(light, range)),
      pigments_(pigments),
      ground_(ground),
      paints_(training_paints(pigments)) {
  const SpectralSampling reference = make_spectral_sampling(light, cmf, 0, range);
  white_xyz_ = reference.white_xyz;
  const std::size_t count = paints_.size();
  const std::vector<float> grid(reference.wavelengths_nm);
  const std::vector<float> by_paint = reflectance_at(grid);  // paint-major
  reflectance_.resize(by_paint.size());
  target_xyz_.assign(count, {0.0, 0.0, 0.0});
  for (std::size_t p = 0; p < count; ++p) {
    for (std::size_t j = 0; j < grid.size(); ++j) {
      const float r = by_paint[p * grid.size() + j];
      reflectance_[j * count + p] = r;
      for (std::size_t c = 0; c < 3; ++c) target_xyz_[p][c] += reference.to_xyz[j][c] * r;
    }
  }
  for (const auto& xyz : target_xyz_) {
    target_lab_.push_back(to_lab(xyz, white_xyz_));
    lab_metric_.push_back(lab_metric(xyz, white_xyz_));
  }
}

std::vector<float> PaletteTrainingSet::reflectance_at(
    const std::vector<float>& wavelengths_nm) const {
  const std::size_t n = wavelengths_nm.size();
  std::vector<float> absorption(pigments_.size() * n), scattering(pigments_.size() * n);
  std::vector<float> ground(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double nm = wavelengths_nm[i];
    for (std::size_t k = 0; k < pigments_.size(); ++k) {
      absorption[k * n + i] = static_cast<float>(pigments_[k].K.at(nm));
      scattering[k * n + i] = static_cast<float>(pigments_[k].S.at(nm));
      if (!(absorption[k * n + i] >= 0.0f) || !(scattering[k * n + i] >= 0.0f) ||
          !std::isfinite(absorption[k * n + i]) || !std::isfinite(scattering[k * n + i])) {
        throw std::runtime_error("node optimisation: pigment '" + pigments_[k].name +
                                 "': K or S at " + std::to_string(nm) +
                                 " nm is negative or not finite");
      }
    }
    ground[i] = static_cast<float>(ground_.at(nm));
  }
  std::vector<float> out(paints_.size() * n);
  for (std::size_t p = 0; p < paints_.size(); ++p) {
    const TrainingPaint& paint = paints_[p];
    for (std::size_t i = 0; i < n; ++i) {
      float k = 0.0f, s = 0.0f;
      for (const auto& [pigment, share] : paint.mix) {
        const std::size_t at = static_cast<std::size_t>(pigment) * n + i;
        km::accumulate_pigment(share, absorption[at], scattering[at], k, s);
      }
      const float below = paint.over_black ? 0.0f : ground[i];
      out[p * n + i] = km::composite(km::layer(k, s, paint.optical_thickness), below);
    }
  }
  return out;
}

RuleError PaletteTrainingSet::error_of(const SpectralSampling& sampling) const {
  const std::size_t n = sampling.wavelengths_nm.size();
  const std::vector<float> reflectance = reflectance_at(sampling.wavelengths_nm);
  RuleError error;
  std::vector<double> differences(target_xyz_.size());
  for (std::size_t p = 0; p < target_xyz_.size(); ++p) {
    const std::array<double, 3> xyz = reflectance_to_xyz(sampling, &reflectance[p * n]);
    differences[p] = de00(target_lab_[p], to_lab(xyz, sampling.white_xyz));
    error.mean_de00 += differences[p];
    error.max_de00 = std::max(error.max_de00, differences[p]);
  }
  error.mean_de00 /= static_cast<double>(target_xyz_.size());
  error.tail_de00 = tail_mean(std::move(differences));
  return error;
}

std::pair<std::vector<std::array<double, 3>>, RuleError> PaletteTrainingSet::fit(
    const std::vector<double>& node_reflectance, int nodes, int stride, int passes) const {
  const auto stride_size = static_cast<std::size_t>(stride);
  const auto paints =
      static_cast<Eigen::Index>((target_xyz_.size() + stride_size - 1) / stride_size);
  const Eigen::Index n = nodes;
  const Eigen::Index m = n - 1;  // free nodes: the last one's weights keep white exact
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(
      node_reflectance.data(), paints, n);

  // With T_last = white − Σ_{i<last} T_i, XYZ = Σ_{i<last} (a_i − a_last) T_i + a_last white:
  // an unconstrained problem in the other nodes' weights.
  const Eigen::MatrixXd reduced = a.leftCols(m).colwise() - a.col(m);
  Eigen::MatrixXd target(paints, 3);
  for (Eigen::Index p = 0; p < paints; ++p) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      target(p, c) =
          target_xyz_[static_cast<std::size_t>(p) * stride_size][static_cast<std::size_t>(c)] -
          a(p, m) * white_xyz_[static_cast<std::size_t>(c)];
    }
  }

  Eigen::VectorXd weight = Eigen::VectorXd::Ones(paints);
  std::vector<std::array<double, 3>> best_readout;
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  RuleError best_error{kInfinity, kInfinity, kInfinity};
  Eigen::MatrixXd normal(3 * m, 3 * m);
  Eigen::VectorXd rhs(3 * m);
  Eigen::VectorXd pair_weight(paints);
  std::vector<double> error_de00(static_cast<std::size_t>(paints));
  std::vector<double> error_lab(static_cast<std::size_t>(paints));
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::array<double, 3>> readout(static_cast<std::size_t>(n));
    if (m > 0) {
      // Minimise Σ_p weight_p · eᵀ M_p e with e the XYZ error and M_p = JᵀJ of XYZ → Lab.
      rhs.setZero();
      for (int pair = 0; pair < 6; ++pair) {
        const int c = kPair[pair][0];
        const int d = kPair[pair][1];
        for (Eigen::Index p = 0; p < paints; ++p) {
          pair_weight[p] = weight[p] * lab_metric_[static_cast<std::size_t>(p) * stride_size]
                                                  [static_cast<std::size_t>(pair)];
        }
        const Eigen::MatrixXd block =
            (reduced.array().colwise() * pair_weight.array()).matrix().transpose() * reduced;
        normal.block(c * m, d * m, m, m) = block;
        if (c != d) normal.block(d * m, c * m, m, m) = block.transpose();
        rhs.segment(c * m, m) += reduced.transpose() * (pair_weight.cwiseProduct(target.col(d)));
        if (c != d) {
          rhs.segment(d * m, m) += reduced.transpose() * (pair_weight.cwiseProduct(target.col(c)));
        }
      }
      const double ridge = kRidge * normal.trace() / static_cast<double>(3 * m);
      normal.diagonal().array() += ridge;
      const Eigen::VectorXd solution = normal.ldlt().solve(rhs);
      for (std::size_t c = 0; c < 3; ++c) {
        double rest = white_xyz_[c];
        for (Eigen::Index i = 0; i < m; ++i) {
          const double w = solution[static_cast<Eigen::Index>(c) * m + i];
          readout[static_cast<std::size_t>(i)][c] = w;
          rest -= w;
        }
        readout[static_cast<std::size_t>(m)][c] = rest;
      }
    } else {
      readout[0] = white_xyz_;
    }

    RuleError error;
    bool finite = true;
    for (Eigen::Index p = 0; p < paints; ++p) {
      std::array<double, 3> xyz{0.0, 0.0, 0.0};
      for (Eigen::Index i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < 3; ++c)
          xyz[c] += a(p, i) * readout[static_cast<std::size_t>(i)][c];
      }
      const auto& metric = lab_metric_[static_cast<std::size_t>(p) * stride_size];
      const auto& goal = target_xyz_[static_cast<std::size_t>(p) * stride_size];
      const std::array<double, 3> e{xyz[0] - goal[0], xyz[1] - goal[1], xyz[2] - goal[2]};
      double lab_squared = 0.0;
      for (int pair = 0; pair < 6; ++pair) {
        const int c = kPair[pair][0];
        const int d = kPair[pair][1];
        lab_squared += (c == d ? 1.0 : 2.0) * metric[static_cast<std::size_t>(pair)] *
                       e[static_cast<std::size_t>(c)] * e[static_cast<std::size_t>(d)];
      }
      const double difference =
          de00(target_lab_[static_cast<std::size_t>(p) * stride_size], to_lab(xyz, white_xyz_));
      finite = finite && std::isfinite(difference);
      error_de00[static_cast<std::size_t>(p)] = difference;
      error_lab[static_cast<std::size_t>(p)] = std::sqrt(std::max(lab_squared, 0.0));
      error.mean_de00 += difference;
      error.max_de00 = std::max(error.max_de00, difference);
    }
    error.mean_de00 /= static_cast<double>(paints);
    error.tail_de00 = tail_mean(error_de00);
    if (!finite) break;
    if (rule_objective(error) < rule_objective(best_error)) {
      best_error = error;
      best_readout = readout;
    }
    if (m == 0) break;

    // Reweight: ΔE00/ΔEab turns the Lab metric into (locally) ΔE00's; ΔE^exponent leans on
    // the worst paints, so the passes move the fit from least squares toward minimax.
    double total = 0.0;
    for (Eigen::Index p = 0; p < paints; ++p) {
      const double de = error_de00[static_cast<std::size_t>(p)];
      const double lab = error_lab[static_cast<std::size_t>(p)];
      const double ratio = lab > 1e-12 ? std::clamp(de / lab, 0.05, 2.0) : 1.0;
      weight[p] *= ratio * ratio * std::pow(std::max(de, kErrorFloor), kMinMaxExponent) /
                   std::pow(std::max(error.mean_de00, kErrorFloor), kMinMaxExponent);
      total += weight[p];
    }
    weight *= static_cast<double>(paints) / total;
  }
  return {best_readout, best_error};
}

void PaletteTrainingSet::fit_readout(SpectralSampling& sampling) const {
  if (sampling.full_spectrum || sampling.wavelengths_nm.empty()) return;
  const std::vector<float> reflectance = reflectance_at(sampling.wavelengths_nm);
  const std::vector<double> values(reflectance.begin(), reflectance.end());
  const auto [readout, error] = fit(values, sampling.size(), 1, kReadoutPasses);
  if (readout.empty()) return;  // nothing finite: keep the weights it came with
  sampling.white_xyz = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < readout.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      sampling.to_xyz[i][c] = static_cast<float>(readout[i][c]);
      sampling.white_xyz[c] += sampling.to_xyz[i][c];
    }
  }
}

}  // namespace impasto::render
