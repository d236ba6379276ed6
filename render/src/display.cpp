#include "impasto/render/display.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include "impasto/render/display_ocio.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace OCIO = OCIO_NAMESPACE;

namespace impasto::render {
namespace {

// XYZ (D65) to linear RGB for sRGB and P3-D65 primaries (IEC 61966-2-1; SMPTE EG 432-1),
// as the 4×4 row-major matrices OCIO's MatrixTransform takes.
constexpr double kXyzToLinearSrgb[16] = {3.2409699419,
                                         -1.5373831776,
                                         -0.4986107603,
                                         0,
                                         -0.9692436363,
                                         1.8759675015,
                                         0.0415550574,
                                         0,
                                         0.0556300797,
                                         -0.2039769589,
                                         1.0569715142,
                                         0,
                                         0,
                                         0,
                                         0,
                                         1};
constexpr double kXyzToLinearP3D65[16] = {2.4934969119,
                                          -0.9313836179,
                                          -0.4027107845,
                                          0,
                                          -0.8294889696,
                                          1.7626640603,
                                          0.0236246858,
                                          0,
                                          0.0358458302,
                                          -0.0761723893,
                                          0.9568845240,
                                          0,
                                          0,
                                          0,
                                          0,
                                          1};

OCIO::TransformRcPtr builtin(const char* style) {
  auto transform = OCIO::BuiltinTransform::Create();
  transform->setStyle(style);
  return transform;
}

OCIO::TransformRcPtr matrix(const double* m44) {
  auto transform = OCIO::MatrixTransform::Create();
  transform->setMatrix(m44);
  return transform;
}

// The piecewise sRGB curve, linear to encoded: the inverse of OCIO's "exponent with linear
// segment" (gamma 2.4, offset 0.055).
OCIO::TransformRcPtr srgb_curve() {
  auto transform = OCIO::ExponentWithLinearTransform::Create();
  const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
  const double offset[4] = {0.055, 0.055, 0.055, 0.0};
  transform->setGamma(gamma);
  transform->setOffset(offset);
  transform->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return transform;
}

}  // namespace

double srgb_encoded(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

double srgb_decoded(double encoded) {
  encoded = std::clamp(encoded, 0.0, 1.0);
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

OCIO::TransformRcPtr display_ocio_transform(DisplayEncoding encoding) {
  switch (encoding) {
    case DisplayEncoding::srgb:
      return builtin("DISPLAY - CIE-XYZ-D65_to_sRGB");
    case DisplayEncoding::rec709:
      return builtin("DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709");
    case DisplayEncoding::rec2020:
      return builtin("DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.2020");
    case DisplayEncoding::display_p3: {
      auto group = OCIO::GroupTransform::Create();
      group->appendTransform(matrix(kXyzToLinearP3D65));
      group->appendTransform(srgb_curve());
      return group;
    }
    case DisplayEncoding::linear_srgb:
      return matrix(kXyzToLinearSrgb);
  }
  throw std::logic_error("unhandled display encoding");
}

DisplayEncoding parse_display_encoding(std::string_view text) {
  return util::parse_name(kDisplayEncodingNames, text, "display encoding");
}

std::string_view to_string(DisplayEncoding encoding) {
  return util::name_of(kDisplayEncodingNames, encoding);
}

const std::vector<std::string>& display_encoding_names() {
  static const std::vector<std::string> names = util::names_of(kDisplayEncodingNames);
  return names;
}

struct DisplayTransform::Impl {
  OCIO::ConstCPUProcessorRcPtr processor;
};

DisplayTransform::DisplayTransform(DisplayEncoding encoding)
    : encoding_(encoding), impl_(std::make_unique<Impl>()) {
  // A raw config suffices: built-in and matrix transforms need no colour spaces or files.
  const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateRaw();
  const OCIO::ConstProcessorRcPtr processor =
      config->getProcessor(display_ocio_transform(encoding));
  impl_->processor = processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                         OCIO::OPTIMIZATION_DEFAULT);
}

DisplayTransform::~DisplayTransform() = default;
DisplayTransform::DisplayTransform(DisplayTransform&&) noexcept = default;
DisplayTransform& DisplayTransform::operator=(DisplayTransform&&) noexcept = default;

void DisplayTransform::apply(float* xyz_to_rgb, std::size_t pixel_count) const {
  if (pixel_count == 0) return;
  OCIO::PackedImageDesc image(xyz_to_rgb, static_cast<long>(pixel_count), 1, 3);
  impl_->processor->apply(image);
}

std::array<double, 9> xyz_to_linear_srgb() {
  const double* m = kXyzToLinearSrgb;
  return {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
}

std::array<double, 9> invert_3x3(const std::array<double, 9>& m) {
  const double c00 = m[4] * m[8] - m[5] * m[7], c01 = m[5] * m[6] - m[3] * m[8],
               c02 = m[3] * m[7] - m[4] * m[6];
  const double inv_det = 1.0 / (m[0] * c00 + m[1] * c01 + m[2] * c02);
  return {
      c00 * inv_det, (m[2] * m[7] - m[1] * m[8]) * inv_det, (m[1] * m[5] - m[2] * m[4]) * inv_det,
      c01 * inv_det, (m[0] * m[8] - m[2] * m[6]) * inv_det, (m[2] * m[3] - m[0] * m[5]) * inv_det,
      c02 * inv_det, (m[1] * m[6] - m[0] * m[7]) * inv_det, (m[0] * m[4] - m[1] * m[3]) * inv_det};
}

}  // namespace impasto::render
