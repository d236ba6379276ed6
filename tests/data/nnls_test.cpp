#include "impasto/data/nnls.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace impasto::data {
namespace {

Eigen::MatrixXd random_matrix(std::mt19937& rng, int rows, int cols) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd m(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) m(i, j) = u(rng);
  }
  return m;
}

// Karush–Kuhn–Tucker conditions of min ½‖Ax − b‖², x ≥ 0, with w = Aᵀ(b − Ax):
// x ≥ 0, w ≤ 0 where x = 0, w = 0 where x > 0.
void expect_kkt(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  const Eigen::VectorXd w = A.transpose() * (b - A * x);
  const double tolerance = 1e-10 * (1.0 + A.norm() * b.norm());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    EXPECT_GE(x[j], 0.0) << j;
    if (x[j] > 0) {
      EXPECT_NEAR(w[j], 0.0, tolerance) << j;
    } else {
      EXPECT_LE(w[j], tolerance) << j;
    }
  }
}

TEST(Nnls, ClipsNegativeComponentsOfAnOrthogonalProblem) {
  const Eigen::VectorXd b = Eigen::Vector3d(1.0, -2.0, 3.0);
  const NnlsResult r = nnls(Eigen::Matrix3d::Identity(), b);
  EXPECT_NEAR(r.x[0], 1.0, 1e-15);
  EXPECT_EQ(r.x[1], 0.0);
  EXPECT_NEAR(r.x[2], 3.0, 1e-15);
  EXPECT_NEAR(r.residual_norm, 2.0, 1e-15);
}

TEST(Nnls, EqualsLeastSquaresWhenThatIsPositive) {
  std::mt19937 rng(7);
  const Eigen::MatrixXd A = random_matrix(rng, 20, 6);
  const Eigen::VectorXd truth = Eigen::VectorXd::LinSpaced(6, 0.5, 3.0);
  const NnlsResult r = nnls(A, A * truth);
  EXPECT_LT((r.x - truth).norm(), 1e-12);
  EXPECT_LT(r.residual_norm, 1e-12);
}

TEST(Nnls, ZeroWhenEveryColumnPointsAway) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  const NnlsResult r = nnls(A, -Eigen::VectorXd::Ones(4));
  EXPECT_EQ(r.x, Eigen::VectorXd::Zero(4));
  EXPECT_EQ(r.iterations, 0);
}

TEST(Nnls, SatisfiesKktOnRandomProblems) {
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 50; ++trial) {
    const int rows = 5 + trial % 20;
    const int cols = 2 + trial % 9;
    const Eigen::MatrixXd A = random_matrix(rng, rows, cols);
    const Eigen::VectorXd b = random_matrix(rng, rows, 1);
    const NnlsResult r = nnls(A, b);
    SCOPED_TRACE(trial);
    expect_kkt(A, b, r.x);
    EXPECT_NEAR(r.residual_norm, (A * r.x - b).norm(), 1e-12);
  }
}

TEST(Nnls, MatchesExhaustiveSearchOverActiveSets) {
  // For few columns the optimum is the best feasible least-squares solution over all 2^n
  // choices of which variables are free: an independent reference.
  std::mt19937 rng(99);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5;
    const Eigen::MatrixXd A = random_matrix(rng, 8, n);
    const Eigen::VectorXd b = random_matrix(rng, 8, 1);
    double best = b.norm();
    for (int mask = 1; mask < (1 << n); ++mask) {
      std::vector<int> free;
      for (int j = 0; j < n; ++j) {
        if (mask & (1 << j)) free.push_back(j);
      }
      Eigen::MatrixXd sub(8, static_cast<Eigen::Index>(free.size()));
      for (std::size_t k = 0; k < free.size(); ++k)
        sub.col(static_cast<Eigen::Index>(k)) = A.col(free[k]);
      const Eigen::VectorXd z = sub.colPivHouseholderQr().solve(b);
      if ((z.array() >= 0).all()) best = std::min(best, (sub * z - b).norm());
    }
    EXPECT_NEAR(nnls(A, b).residual_norm, best, 1e-12) << trial;
  }
}

TEST(Nnls, RejectsBadInput) {
  EXPECT_THROW(nnls(Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Ones(2)), std::runtime_error);
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  A(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(nnls(A, Eigen::VectorXd::Ones(2)), std::runtime_error);
}

}  // namespace
}  // namespace impasto::data
