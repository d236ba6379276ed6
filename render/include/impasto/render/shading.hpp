#pragma once
// Per-cell shading of the paint surface: the reference the GLSL shaders mirror. The canvas
// lies in the x-y plane (x right, y down the image rows), heights in mm along +z toward the
// viewer, who looks straight down. Angles in radians.
#include <algorithm>
#include <cmath>

#include "impasto/util/vec3.hpp"

namespace impasto::render::shade {

// util's 3-vector, in float as the shaders compute.
using Vec3 = util::Vec3<float>;
using util::dot;

// v over its length, as GLSL's normalize divides; a zero vector gives the canvas's normal.
inline Vec3 normalized_or_up(Vec3 v) {
  const float length = std::sqrt(dot(v, v));
  return length > 0.0f ? Vec3{v.x / length, v.y / length, v.z / length} : Vec3{0.0f, 0.0f, 1.0f};
}

// Unit vector toward a directional light at azimuth (from +x toward +y) and elevation above
// the canvas plane.
inline Vec3 light_direction(float azimuth, float elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

// Surface normal from central differences of total height (mm): the neighbours left/right
// and up/down, cell_size_mm apart from the centre (so 2·cell_size between them).
inline Vec3 height_normal(float left, float right, float up, float down, float cell_size_mm) {
  const float inv_span = 0.5f / cell_size_mm;
  return normalized_or_up({-(right - left) * inv_span, -(down - up) * inv_span, 1.0f});
}

// The surface parameters, blended between dry and wet paint by the cell's wetness.
struct Material {
  float specular;   // Blinn-Phong specular strength (fraction of the light's white)
  float shininess;  // Blinn-Phong exponent
};

inline Material blend(Material dry, Material wet, float wetness) {
  const float w = std::clamp(wetness, 0.0f, 1.0f);
  return {dry.specular + w * (wet.specular - dry.specular),
          dry.shininess + w * (wet.shininess - dry.shininess)};
}

// The factors that turn a cell's diffuse (K-M) colour and the light's white into its shaded
// colour: colour = diffuse · diffuse_factor + white · specular_factor.
struct Shading {
  float diffuse;
  float specular;
};

// How much of the light reaches a cell past the relief (relief_shading.hpp): the share of
// the light's disc in view, and the share of the sky (ambient) left open. 1, 1 on flat canvas.
struct Visibility {
  float shadow = 1.0f;
  float occlusion = 1.0f;
};

// How much the occlusion dims the direct (Lambert) light, against the ambient light it
// scales fully: a furrow darkens a little even under a high light. The GLSL gets it as a
// #define from CanvasRenderer.
inline constexpr float kOcclusionDirectShare = 0.3f;

// Lambert plus ambient, normalised so that flat canvas shows its K-M reflectance exactly
// (the K-M data describe paint seen at the light's elevation), plus the surface's own light:
// Blinn-Phong specular of the direct light (its share, 1 - ambient) for a viewer straight
// above (view vector +z), and `sky_reflectance` of the ambient light, the share of a uniform
// sky the surface reflects (the paint's k1 when its body is seen through its surface,
// RenderSettings::saunderson; 0: none). Under a uniform sky a flat layer so shows body + k1,
// what an instrument that includes the surface reads. The relief's shadow dims the direct
// light and its highlight; its occlusion dims the ambient light and its reflection and, by
// kOcclusionDirectShare, the direct light (both 1 leave the terms as they are, bit for bit).
inline Shading blinn_phong(Vec3 normal, Vec3 to_light, float ambient, Material material,
                           Visibility visibility = {}, float sky_reflectance = 0.0f) {
  const float flat_lambert = std::max(to_light.z, 0.05f);
  const float lambert = std::max(dot(normal, to_light), 0.0f) / flat_lambert;
  const Vec3 half_vector = normalized_or_up({to_light.x, to_light.y, to_light.z + 1.0f});
  const float n_dot_h = std::max(dot(normal, half_vector), 0.0f);
  const float specular = dot(normal, to_light) > 0.0f
                             ? material.specular * std::pow(n_dot_h, material.shininess)
                             : 0.0f;
  const float direct =
      visibility.shadow * (1.0f - kOcclusionDirectShare * (1.0f - visibility.occlusion));
  return {ambient * visibility.occlusion + (1.0f - ambient) * lambert * direct,
          (1.0f - ambient) * specular * visibility.shadow +
              ambient * sky_reflectance * visibility.occlusion};
}

}  // namespace impasto::render::shade
