#include "impasto/data/ks_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "impasto/data/nnls.hpp"

namespace impasto::data {
namespace {

// Reflectances this close to 0 would make Q_R infinite; measurements are never that dark.
constexpr double kMinimumReflectance = 1e-6;

void check(const KsFitProblem& problem) {
  const std::size_t n = problem.pigment_names.size();
  if (n == 0) throw std::runtime_error("K/S fit: no pigments");
  if (problem.samples.empty()) throw std::runtime_error("K/S fit: no samples");
  const auto reference = std::find(problem.pigment_names.begin(), problem.pigment_names.end(),
                                   problem.reference_pigment);
  if (reference == problem.pigment_names.end()) {
    throw std::runtime_error("K/S fit: the reference pigment '" + problem.reference_pigment +
                             "' is in no sample");
  }
  std::vector<bool> used(n, false);
  for (const KsSample& sample : problem.samples) {
    if (sample.concentrations.size() != n) {
      throw std::runtime_error("K/S fit: sample '" + sample.name + "' has " +
                               std::to_string(sample.concentrations.size()) +
                               " concentrations for " + std::to_string(n) + " pigments");
    }
    double total = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const double c = sample.concentrations[j];
      if (!std::isfinite(c) || c < 0) {
        throw std::runtime_error("K/S fit: sample '" + sample.name +
                                 "' has a negative or non-finite concentration");
      }
      total += c;
      if (c > 0) used[j] = true;
    }
    if (total <= 0) throw std::runtime_error("K/S fit: sample '" + sample.name + "' is empty");
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (!used[j]) {
      throw std::runtime_error("K/S fit: pigment '" + problem.pigment_names[j] +
                               "' is in no sample");
    }
  }
}

double internal_reflectance(double measured, const std::optional<Saunderson>& saunderson) {
  const double r = saunderson ? saunderson->to_internal(measured) : measured;
  return std::clamp(r, kMinimumReflectance, 1.0);
}

}  // namespace

KsFitResult fit_kubelka_munk(const KsFitProblem& problem) {
  check(problem);
  const std::vector<double> grid = problem.grid_nm.empty()
                                       ? problem.samples.front().reflectance.wavelengths_nm
                                       : problem.grid_nm;
  const auto M = static_cast<Eigen::Index>(problem.samples.size());
  const auto N = static_cast<Eigen::Index>(problem.pigment_names.size());
  const auto ref =
      static_cast<Eigen::Index>(std::find(problem.pigment_names.begin(),
                                          problem.pigment_names.end(), problem.reference_pigment) -
                                problem.pigment_names.begin());

  Eigen::MatrixXd C(M, N);
  for (Eigen::Index i = 0; i < M; ++i) {
    for (Eigen::Index j = 0; j < N; ++j) {
      C(i, j) =
          problem.samples[static_cast<std::size_t>(i)].concentrations[static_cast<std::size_t>(j)];
    }
  }

  KsFitResult result;
  for (const auto& name : problem.pigment_names) {
    result.pigments.push_back(Pigment{name,
                                      Spectrum{"K", grid, std::vector<double>(grid.size())},
                                      Spectrum{"S", grid, std::vector<double>(grid.size())},
                                      {}});
  }
  std::vector<double> equation_sq(static_cast<std::size_t>(M), 0.0);

  // Unknowns x = [K_0..K_{N−1}, S_j for j ≠ ref]; S_ref = 1 moves Q·C_ref to the right side.
  Eigen::MatrixXd A(M, 2 * N - 1);
  Eigen::VectorXd Q(M);
  for (std::size_t w = 0; w < grid.size(); ++w) {
    for (Eigen::Index i = 0; i < M; ++i) {
      const KsSample& sample = problem.samples[static_cast<std::size_t>(i)];
      const double measured = sample.reflectance.at(grid[w]);
      if (!(measured >= 0.0 && measured <= 1.0)) {
        throw std::runtime_error("K/S fit: sample '" + sample.name + "' has reflectance " +
                                 std::to_string(measured) + " at " + std::to_string(grid[w]) +
                                 " nm (outside its range or 0..1)");
      }
      Q[i] = ks_from_reflectance(internal_reflectance(measured, problem.saunderson));
    }
    A.leftCols(N) = C;
    for (Eigen::Index j = 0, col = N; j < N; ++j) {
      if (j != ref) A.col(col++) = -Q.cwiseProduct(C.col(j));
    }
    const Eigen::VectorXd b = Q.cwiseProduct(C.col(ref));
    const NnlsResult solution = nnls(A, b);

    for (Eigen::Index j = 0, col = N; j < N; ++j) {
      Pigment& p = result.pigments[static_cast<std::size_t>(j)];
      p.K.values[w] = solution.x[j];
      p.S.values[w] = j == ref ? 1.0 : solution.x[col++];
    }
    const Eigen::VectorXd residual = A * solution.x - b;
    for (Eigen::Index i = 0; i < M; ++i)
      equation_sq[static_cast<std::size_t>(i)] += residual[i] * residual[i];
  }

  std::vector<const Pigment*> pigments;
  for (const Pigment& p : result.pigments) pigments.push_back(&p);
  for (std::size_t i = 0; i < problem.samples.size(); ++i) {
    const KsSample& sample = problem.samples[i];
    const Spectrum fitted =
        mixture_reflectance(pigments, sample.concentrations, problem.saunderson);
    KsSampleResidual r{sample.name, std::sqrt(equation_sq[i] / static_cast<double>(grid.size())), 0,
                       0};
    double sum_sq = 0;
    for (std::size_t w = 0; w < grid.size(); ++w) {
      const double error = fitted.values[w] - sample.reflectance.at(grid[w]);
      sum_sq += error * error;
      r.max_reflectance = std::max(r.max_reflectance, std::abs(error));
    }
    r.rms_reflectance = std::sqrt(sum_sq / static_cast<double>(grid.size()));
    result.residuals.push_back(r);
  }
  return result;
}

Spectrum mixture_reflectance(const std::vector<const Pigment*>& pigments,
                             const std::vector<double>& concentrations,
                             const std::optional<Saunderson>& saunderson) {
  if (pigments.empty() || pigments.size() != concentrations.size()) {
    throw std::runtime_error("mixture_reflectance: need one concentration per pigment");
  }
  const std::vector<double>& grid = pigments.front()->K.wavelengths_nm;
  Spectrum out{"mixture", grid, std::vector<double>(grid.size())};
  for (std::size_t w = 0; w < grid.size(); ++w) {
    double k = 0, s = 0;
    for (std::size_t j = 0; j < pigments.size(); ++j) {
      k += concentrations[j] * pigments[j]->K.at(grid[w]);
      s += concentrations[j] * pigments[j]->S.at(grid[w]);
    }
    // No scattering at all: an opaque layer of pure absorber reflects nothing.
    const double r = reflectance_infinite(k, s);
    out.values[w] = saunderson ? saunderson->to_measured(r) : r;
  }
  return out;
}

}  // namespace impasto::data
