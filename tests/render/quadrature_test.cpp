// Golub–Welsch on a discrete measure: exactness, positivity, nodes inside the support.
#include "impasto/render/gaussian_quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

using impasto::render::gauss_rule;
using impasto::render::QuadratureRule;

namespace {

// A measure shaped like a light times the CIE functions: smooth hump plus spikes, on 1 nm.
struct Measure {
  std::vector<double> points, masses;
};

Measure spiky_measure() {
  Measure m;
  for (int nm = 360; nm <= 750; ++nm) {
    const double x = nm;
    double w = std::exp(-0.5 * std::pow((x - 560.0) / 60.0, 2.0)) +
               0.5 * std::exp(-0.5 * std::pow((x - 450.0) / 20.0, 2.0));
    if (nm == 436 || nm == 546 || nm == 611) w += 3.0;  // mercury / europium lines
    m.points.push_back(x);
    m.masses.push_back(w);
  }
  return m;
}

// Σ masses p(t) and Σ weights p(t) for p(t) = t^k, t = (x − 555) / 195 in [−1, 1].
double moment(const std::vector<double>& x, const std::vector<double>& w, int k) {
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) sum += w[i] * std::pow((x[i] - 555.0) / 195.0, k);
  return sum;
}

}  // namespace

TEST(GaussRule, ExactForPolynomialsUpToDegree2NMinus1) {
  const Measure m = spiky_measure();
  for (int n = 1; n <= 16; ++n) {
    const QuadratureRule rule = gauss_rule(m.points, m.masses, n);
    ASSERT_EQ(rule.nodes.size(), static_cast<std::size_t>(n));
    for (int k = 0; k <= 2 * n - 1; ++k) {
      const double exact = moment(m.points, m.masses, k);
      const double scale = moment(m.points, m.masses, 0);
      EXPECT_NEAR(moment(rule.nodes, rule.weights, k), exact, 1e-10 * scale)
          << "n = " << n << ", degree " << k;
    }
  }
}

TEST(GaussRule, NotExactBeyondDegree2N) {
  // The rule must be a genuine n-point rule: degree 2n is generally not integrated exactly.
  const Measure m = spiky_measure();
  const QuadratureRule rule = gauss_rule(m.points, m.masses, 3);
  const double exact = moment(m.points, m.masses, 6);
  EXPECT_GT(std::abs(moment(rule.nodes, rule.weights, 6) - exact), 1e-6 * exact);
}

TEST(GaussRule, NodesInsideAndWeightsPositiveSummingToMass) {
  const Measure m = spiky_measure();
  const double total = std::accumulate(m.masses.begin(), m.masses.end(), 0.0);
  for (int n : {1, 2, 8, 16}) {
    const QuadratureRule rule = gauss_rule(m.points, m.masses, n);
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      EXPECT_GE(rule.nodes[i], m.points.front());
      EXPECT_LE(rule.nodes[i], m.points.back());
      EXPECT_GT(rule.weights[i], 0.0);
      if (i > 0) {
        EXPECT_GT(rule.nodes[i], rule.nodes[i - 1]);
      }
    }
    EXPECT_NEAR(std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0), total,
                1e-12 * total);
  }
}

TEST(GaussRule, OnePointRuleIsTheMean) {
  const Measure m = spiky_measure();
  const QuadratureRule rule = gauss_rule(m.points, m.masses, 1);
  double mean = 0.0, total = 0.0;
  for (std::size_t j = 0; j < m.points.size(); ++j) {
    mean += m.masses[j] * m.points[j];
    total += m.masses[j];
  }
  EXPECT_NEAR(rule.nodes[0], mean / total, 1e-9);
}

TEST(GaussRule, FullRuleOnFewPointsReproducesTheMeasure) {
  // With as many nodes as points of positive mass, the rule is the measure itself.
  const std::vector<double> points{400.0, 500.0, 550.0, 600.0, 700.0};
  const std::vector<double> masses{1.0, 0.0, 2.0, 0.5, 0.25};
  const QuadratureRule rule = gauss_rule(points, masses, 4);
  const std::vector<double> expected_nodes{400.0, 550.0, 600.0, 700.0};
  const std::vector<double> expected_weights{1.0, 2.0, 0.5, 0.25};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(rule.nodes[i], expected_nodes[i], 1e-8);
    EXPECT_NEAR(rule.weights[i], expected_weights[i], 1e-10);
  }
}

TEST(GaussRule, RejectsBadMeasures) {
  const std::vector<double> points{400.0, 500.0, 600.0};
  EXPECT_THROW(gauss_rule(points, std::vector<double>{1.0, 1.0}, 1), std::runtime_error);
  EXPECT_THROW(gauss_rule(points, std::vector<double>{1.0, -1.0, 1.0}, 1), std::runtime_error);
  EXPECT_THROW(gauss_rule(points, std::vector<double>{1.0, NAN, 1.0}, 1), std::runtime_error);
  EXPECT_THROW(
      gauss_rule(std::vector<double>{400.0, 400.0, 600.0}, std::vector<double>{1.0, 1.0, 1.0}, 1),
      std::runtime_error);
  EXPECT_THROW(gauss_rule(points, std::vector<double>{1.0, 0.0, 1.0}, 3), std::runtime_error);
  EXPECT_THROW(gauss_rule(points, std::vector<double>{1.0, 1.0, 1.0}, 0), std::runtime_error);
}
