// Cast shadows and ambient occlusion of the paint relief: a line-by-line port of
// render/include/impasto/render/relief_shading.hpp (the CPU reference; see its comments).
// RELIEF_DIRECTIONS comes from the C++ constant (shader_library.cpp). Heights are the g
// channel of the surface texture, read clamped to the canvas as the normals read them.

uniform bool relief_shadows;
uniform bool relief_occlusion;
uniform vec2 relief_step;          // cells a step; one component is ±1
uniform float relief_step_mm;
uniform int relief_shadow_steps;
uniform vec4 relief_light;         // elevation, angular radius (rad), tan_low, tan_high
uniform ivec2 relief_occlusion_steps;  // along the axes, along the diagonals
uniform float relief_max_height;   // bounds every height of the canvas (mm)

float relief_height(sampler2D heights, ivec2 size, int x, int y) {
  return texelFetch(heights, clamp(ivec2(x, y), ivec2(0), size - 1), 0).g;
}

float relief_visible_disc_share(float horizon, float elevation, float r) {
  float t = clamp((horizon - elevation) / r, -1.0, 1.0);
  return (acos(t) - t * sqrt(1.0 - t * t)) * 0.318309886183790671538;
}

float relief_shadow(sampler2D heights, ivec2 size, ivec2 cell) {
  float h0 = relief_height(heights, size, cell.x, cell.y);
  float max_tan = 0.0;
  bool along_x = abs(relief_step.x) >= abs(relief_step.y);
  for (int i = 1; i <= relief_shadow_steps; ++i) {
    float distance = float(i) * relief_step_mm;
    if (relief_max_height - h0 <= distance * max(max_tan, relief_light.z)) break;
    float minor = float(along_x ? cell.y : cell.x) + float(i) * (along_x ? relief_step.y : relief_step.x);
    float m0 = floor(minor);
    float f = minor - m0;
    int major = (along_x ? cell.x : cell.y) + i * int(along_x ? relief_step.x : relief_step.y);
    int mi = int(m0);
    float a = along_x ? relief_height(heights, size, major, mi) : relief_height(heights, size, mi, major);
    float b = along_x ? relief_height(heights, size, major, mi + 1)
                      : relief_height(heights, size, mi + 1, major);
    float h = a + f * (b - a);
    max_tan = max(max_tan, (h - h0) / distance);
    if (max_tan >= relief_light.w) return 0.0;
  }
  if (max_tan <= 0.0) return 1.0;
  return relief_visible_disc_share(atan(max_tan), relief_light.x, relief_light.y);
}

float relief_ambient_occlusion(sampler2D heights, ivec2 size, ivec2 cell, float cell_mm) {
  const ivec2 directions[8] = ivec2[](ivec2(1, 0), ivec2(1, 1), ivec2(0, 1), ivec2(-1, 1),
                                      ivec2(-1, 0), ivec2(-1, -1), ivec2(0, -1), ivec2(1, -1));
  float h0 = relief_height(heights, size, cell.x, cell.y);
  float open = 0.0;
  for (int d = 0; d < RELIEF_DIRECTIONS; ++d) {
    ivec2 direction = directions[d];
    bool diagonal = direction.x != 0 && direction.y != 0;
    int steps = diagonal ? relief_occlusion_steps.y : relief_occlusion_steps.x;
    float step_mm = diagonal ? cell_mm * 1.41421356237309504880 : cell_mm;
    float max_tan = 0.0;
    for (int i = 1; i <= steps; ++i) {
      ivec2 at = cell + i * direction;
      float h = relief_height(heights, size, at.x, at.y);
      max_tan = max(max_tan, (h - h0) / (float(i) * step_mm));
    }
    open += 1.0 / (1.0 + max_tan * max_tan);
  }
  return open * (1.0 / float(RELIEF_DIRECTIONS));
}

// (shadow, occlusion) of a cell: (1, 1) where switched off.
vec2 relief_visibility(sampler2D heights, ivec2 size, ivec2 cell, float cell_mm) {
  return vec2(relief_shadows ? relief_shadow(heights, size, cell) : 1.0,
              relief_occlusion ? relief_ambient_occlusion(heights, size, cell, cell_mm) : 1.0);
}
