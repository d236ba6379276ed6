#include "impasto/data/nnls.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace impasto::data {
namespace {

// The unconstrained least-squares solution on the passive columns, scattered back into a
// full-length vector (zero on the active columns).
Eigen::VectorXd solve_on_passive_set(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                     const std::vector<bool>& passive) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    if (passive[static_cast<std::size_t>(j)]) columns.push_back(j);
  }
  Eigen::VectorXd s = Eigen::VectorXd::Zero(A.cols());
  if (columns.empty()) return s;
  Eigen::MatrixXd A_passive(A.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) {
    A_passive.col(static_cast<Eigen::Index>(k)) = A.col(columns[k]);
  }
  const Eigen::VectorXd z = A_passive.colPivHouseholderQr().solve(b);
  for (std::size_t k = 0; k < columns.size(); ++k) s[columns[k]] = z[static_cast<Eigen::Index>(k)];
  return s;
}

}  // namespace

NnlsResult nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int max_iterations) {
  if (A.rows() != b.size()) {
    throw std::runtime_error("nnls: A has " + std::to_string(A.rows()) + " rows but b has " +
                             std::to_string(b.size()) + " entries");
  }
  if (!A.allFinite() || !b.allFinite()) throw std::runtime_error("nnls: non-finite input");
  const Eigen::Index n = A.cols();
  if (max_iterations <= 0) max_iterations = 3 * static_cast<int>(std::max<Eigen::Index>(n, 1));

  // Gradient entries below this are rounding noise (the tolerance of Lawson–Hanson's code).
  const double norm1 = n > 0 ? A.cwiseAbs().colwise().sum().maxCoeff() : 0.0;
  const double tolerance = 10.0 * std::numeric_limits<double>::epsilon() * norm1 *
                           static_cast<double>(std::max(A.rows(), n));

  NnlsResult result;
  result.x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<std::size_t>(n), false);
  Eigen::VectorXd w = A.transpose() * b;  // −gradient of ½‖Ax − b‖² at x = 0

  for (;;) {
    // Free the active variable whose increase lowers the residual fastest.
    Eigen::Index entering = -1;
    double best = tolerance;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[static_cast<std::size_t>(j)] && w[j] > best) {
        best = w[j];
        entering = j;
      }
    }
    if (entering < 0) break;  // KKT satisfied
    passive[static_cast<std::size_t>(entering)] = true;

    for (bool first_pass = true;; first_pass = false) {
      if (++result.iterations > max_iterations) {
        throw std::runtime_error("nnls: no convergence in " + std::to_string(max_iterations) +
                                 " iterations");
      }
      const Eigen::VectorXd s = solve_on_passive_set(A, b, passive);
      if (first_pass && s[entering] <= 0.0) {
        // Rounding made the entering variable useless: keep it active and ignore its gradient.
        passive[static_cast<std::size_t>(entering)] = false;
        w[entering] = 0.0;
        break;
      }
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && s[j] <= 0.0) feasible = false;
      }
      if (feasible) {
        result.x = s;
        w = A.transpose() * (b - A * result.x);
        break;
      }
      // Step from x towards s until the first passive variable reaches zero; drop it.
      double alpha = std::numeric_limits<double>::infinity();
      Eigen::Index blocking = -1;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && s[j] <= 0.0) {
          const double step = result.x[j] / (result.x[j] - s[j]);
          if (step < alpha) {
            alpha = step;
            blocking = j;
          }
        }
      }
      result.x += alpha * (s - result.x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && (j == blocking || result.x[j] <= 0.0)) {
          passive[static_cast<std::size_t>(j)] = false;
          result.x[j] = 0.0;
        }
      }
    }
  }
  result.residual_norm = (A * result.x - b).norm();
  return result;
}

}  // namespace impasto::data
