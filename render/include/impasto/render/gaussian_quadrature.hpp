#pragma once
// Gaussian quadrature for a discrete, non-negative measure (Golub–Welsch).
#include <span>
#include <vector>

namespace impasto::render {

// An n-point rule: Σ_i weights[i] f(nodes[i]) approximates Σ_j masses[j] f(points[j]).
struct QuadratureRule {
  std::vector<double> nodes;    // increasing, inside [points.front(), points.back()]
  std::vector<double> weights;  // all > 0, summing to the total mass
};

// The n-point Gaussian rule of the discrete measure Σ_j masses[j] δ(x − points[j]): exact
// for every polynomial of degree <= 2n − 1. The three-term recurrence of its orthogonal
// polynomials comes from Lanczos iteration on diag(points) with full reorthogonalisation
// (stable where the plain Stieltjes recurrence loses orthogonality), then the nodes and
// weights from the eigen-decomposition of the Jacobi matrix.
// Throws std::runtime_error for mismatched sizes, unsorted points, negative or non-finite
// masses, or n outside [1, number of points with positive mass].
QuadratureRule gauss_rule(std::span<const double> points, std::span<const double> masses, int n);

}  // namespace impasto::render
