#include "impasto/render/gaussian_quadrature.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::render {
namespace {

void check_measure(std::span<const double> points, std::span<const double> masses, int n) {
  if (points.size() != masses.size()) {
    throw std::runtime_error("gauss_rule: " + std::to_string(points.size()) + " points but " +
                             std::to_string(masses.size()) + " masses");
  }
  std::size_t positive = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (!std::isfinite(points[j]) || (j > 0 && !(points[j] > points[j - 1]))) {
      throw std::runtime_error(
          "gauss_rule: points must be finite and strictly increasing (at "
          "index " +
          std::to_string(j) + ")");
    }
    if (!std::isfinite(masses[j]) || masses[j] < 0.0) {
      throw std::runtime_error("gauss_rule: mass at index " + std::to_string(j) +
                               " is negative or not finite");
    }
    positive += masses[j] > 0.0 ? 1 : 0;
  }
  if (n < 1 || static_cast<std::size_t>(n) > positive) {
    throw std::runtime_error("gauss_rule: " + std::to_string(n) +
                             " nodes requested but the measure has " + std::to_string(positive) +
                             " points of positive mass");
  }
}

double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.dot(b);
}

}  // namespace

QuadratureRule gauss_rule(std::span<const double> points, std::span<const double> masses, int n) {
  check_measure(points, masses, n);
  const auto m = static_cast<Eigen::Index>(points.size());

  // Work on t = (x − centre) / half_width in [−1, 1] so the recurrence is well scaled.
  const double centre = 0.5 * (points.front() + points.back());
  const double half_width = std::max(0.5 * (points.back() - points.front()), 1e-300);
  Eigen::VectorXd t(m);
  Eigen::VectorXd sqrt_mass(m);
  double total_mass = 0.0;
  for (Eigen::Index j = 0; j < m; ++j) {
    t[j] = (points[static_cast<std::size_t>(j)] - centre) / half_width;
    sqrt_mass[j] = std::sqrt(masses[static_cast<std::size_t>(j)]);
    total_mass += masses[static_cast<std::size_t>(j)];
  }

  // Lanczos on A = diag(t) from q0 = sqrt(mass) / |sqrt(mass)|: the tridiagonal matrix it
  // builds is the Jacobi matrix of the measure's orthonormal polynomials.
  Eigen::MatrixXd q(m, n);
  Eigen::VectorXd diagonal(n);
  Eigen::VectorXd off_diagonal(std::max(n - 1, 1));
  q.col(0) = sqrt_mass / std::sqrt(total_mass);
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd r = t.cwiseProduct(q.col(k));
    diagonal[k] = dot(q.col(k), r);
    if (k + 1 == n) {
      break;
    }
    // Full reorthogonalisation, twice ("twice is enough", Parlett): keeps the recurrence
    // exact to rounding even when the measure is spiky (fluorescent lights).
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i <= k; ++i) {
        r -= dot(q.col(i), r) * q.col(i);
      }
    }
    const double norm = r.norm();
    if (!(norm > 0.0)) {
      throw std::runtime_error("gauss_rule: the measure supports fewer than " + std::to_string(n) +
                               " nodes");
    }
    off_diagonal[k] = norm;
    q.col(k + 1) = r / norm;
  }

  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off_diagonal.head(n - 1), Eigen::ComputeEigenvectors);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("gauss_rule: eigen-decomposition of the Jacobi matrix failed");
  }

  QuadratureRule rule;
  rule.nodes.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {  // eigenvalues come sorted increasing
    const double first_component = solver.eigenvectors()(0, i);
    rule.nodes[static_cast<std::size_t>(i)] =
        std::clamp(centre + half_width * solver.eigenvalues()[i], points.front(), points.back());
    rule.weights[static_cast<std::size_t>(i)] = total_mass * first_component * first_component;
  }
  return rule;
}

}  // namespace impasto::render
