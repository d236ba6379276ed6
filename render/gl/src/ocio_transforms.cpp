#include "ocio_transforms.hpp"

#include <stdexcept>

namespace OCIO = OCIO_NAMESPACE;

namespace impasto::render_gl {
namespace {

// XYZ (D65) to linear RGB for sRGB and P3-D65 primaries (IEC 61966-2-1; SMPTE EG 432-1).
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

// Linear to the piecewise sRGB curve (gamma 2.4, offset 0.055).
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

OCIO::TransformRcPtr display_ocio_transform(render::DisplayEncoding encoding) {
  using render::DisplayEncoding;
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

}  // namespace impasto::render_gl
