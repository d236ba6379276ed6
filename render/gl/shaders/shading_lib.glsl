// Per-cell shading: a port of render/include/impasto/render/shading.hpp (the CPU reference).
// Canvas in the x-y plane (x right, y down the rows), heights along +z toward the viewer.

vec3 shade_normalized(vec3 v) {
  float length_v = sqrt(dot(v, v));
  return length_v > 0.0 ? v / length_v : vec3(0.0, 0.0, 1.0);
}

// Normal from central differences of total height (mm), neighbours cell_mm from the centre.
vec3 shade_height_normal(float left, float right, float up, float down, float cell_mm) {
  float inv_span = 0.5 / cell_mm;
  return shade_normalized(vec3(-(right - left) * inv_span, -(down - up) * inv_span, 1.0));
}

// Material blend by wetness: x = specular strength, y = shininess.
vec2 shade_blend(vec2 dry, vec2 wet, float wetness) {
  float w = clamp(wetness, 0.0, 1.0);
  return dry + w * (wet - dry);
}

// Lambert + ambient normalised to flat canvas (x); the surface's own light (y): Blinn-Phong
// specular of the direct light's share for a viewer straight above, and sky_reflectance of
// the ambient light (the paint's k1, 0 without its surface); visibility = (shadow,
// occlusion) of the relief (relief_lib), (1, 1) on flat canvas. The C++ reference is
// shade::blinn_phong. SHADE_OCCLUSION_DIRECT_SHARE comes from shade::kOcclusionDirectShare.
vec2 shade_blinn_phong(vec3 normal, vec3 to_light, float ambient, vec2 material, vec2 visibility,
                       float sky_reflectance) {
  float flat_lambert = max(to_light.z, 0.05);
  float lambert = max(dot(normal, to_light), 0.0) / flat_lambert;
  vec3 half_vector = shade_normalized(vec3(to_light.x, to_light.y, to_light.z + 1.0));
  float n_dot_h = max(dot(normal, half_vector), 0.0);
  float specular = dot(normal, to_light) > 0.0 ? material.x * pow(n_dot_h, material.y) : 0.0;
  float direct = visibility.x * (1.0 - SHADE_OCCLUSION_DIRECT_SHARE * (1.0 - visibility.y));
  return vec2(ambient * visibility.y + (1.0 - ambient) * lambert * direct,
              (1.0 - ambient) * specular * visibility.x + ambient * sky_reflectance * visibility.y);
}

vec2 shade_blinn_phong(vec3 normal, vec3 to_light, float ambient, vec2 material) {
  return shade_blinn_phong(normal, to_light, ambient, material, vec2(1.0), 0.0);
}
