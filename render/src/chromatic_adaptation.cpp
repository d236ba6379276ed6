#include "impasto/render/chromatic_adaptation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::render {
namespace {

// Lam's Bradford cone-response matrix.
constexpr Matrix3 kBradford{
    {{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};

}  // namespace

ChromaticAdaptation parse_chromatic_adaptation(std::string_view text) {
  return util::parse_name(kChromaticAdaptationNames, text, "chromatic adaptation");
}

Matrix3 identity_matrix() {
  return {{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 product{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) sum += a[r][k] * b[k][c];
      product[r][c] = sum;
    }
  }
  return product;
}

Xyz apply(const Matrix3& m, const Xyz& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Matrix3 inverse(const Matrix3& m) {
  // Cofactors over the determinant: exact enough for these well-conditioned matrices, and
  // an adaptation from a white to itself comes out as the identity to rounding.
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double determinant = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  if (!(std::abs(determinant) > 1e-300)) {
    throw std::runtime_error("inverse: singular 3x3 matrix");
  }
  const double s = 1.0 / determinant;
  return {{{c00 * s, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * s,
            (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s},
           {c01 * s, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s,
            (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s},
           {c02 * s, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s,
            (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s}}};
}

Matrix3 bradford_matrix(const Xyz& source_white, const Xyz& target_white) {
  const Xyz source_cone = apply(kBradford, source_white);
  const Xyz target_cone = apply(kBradford, target_white);
  Matrix3 gain{};
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(source_cone[i]) > 0.0) || !std::isfinite(source_cone[i])) {
      throw std::runtime_error(
          "chromatic adaptation: the source white has no response in "
          "cone channel " +
          std::to_string(i));
    }
    gain[i][i] = target_cone[i] / source_cone[i];
  }
  return multiply(inverse(kBradford), multiply(gain, kBradford));
}

}  // namespace impasto::render
