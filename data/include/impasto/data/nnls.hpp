#pragma once
// Non-negative least squares, which Eigen lacks: min ‖A·x − b‖₂ subject to x ≥ 0.
#include <Eigen/Dense>

namespace impasto::data {

struct NnlsResult {
  Eigen::VectorXd x;         // the minimiser, every entry >= 0
  double residual_norm = 0;  // ‖A·x − b‖₂
  int iterations = 0;        // least-squares solves on the passive set
};

// Lawson & Hanson's active-set method ("Solving Least Squares Problems", 1974, ch. 23).
// At the solution the KKT conditions hold: w = Aᵀ(b − A·x) ≤ 0 where x = 0 and w = 0
// where x > 0 (up to rounding). max_iterations <= 0 means 3·columns. Throws
// std::runtime_error on mismatched sizes, non-finite input or no convergence.
NnlsResult nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int max_iterations = 0);

}  // namespace impasto::data
