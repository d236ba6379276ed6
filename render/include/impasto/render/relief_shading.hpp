#pragma once
// Light hidden by the paint relief: cast shadows softened by the light's angular size, and
// ambient occlusion from horizon angles (Max 1988, "Horizon mapping"). The CPU reference;
// render/gl/shaders/relief_lib.glsl mirrors it line by line and takes its constants from
// here (CanvasRenderer writes them as #defines). Heights in mm on a grid of cells cell_mm
// wide, read with clamping at the canvas edges as the normals read them. A flat canvas gets
// shadow 1 and occlusion 1 exactly, so it renders as without them.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

namespace impasto::render {
struct RenderSettings;
}

namespace impasto::render::relief {

// Horizon directions of the occlusion: the axes and diagonals, so every sample is a cell.
inline constexpr int kOcclusionDirections = 8;

// A canvas-sized height field (row-major, total height in mm).
struct HeightField {
  const float* heights = nullptr;
  int width = 0, height = 0;
  float at(int x, int y) const {
    return heights[static_cast<std::size_t>(std::clamp(y, 0, height - 1)) *
                       static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(std::clamp(x, 0, width - 1))];
  }
};

// The march toward the light and the occlusion radius, in cells, for one light and grid.
struct ReliefParams {
  bool shadows = false;
  bool occlusion = false;
  // Shadow march: one step moves exactly one cell along the dominant axis of the light's
  // azimuth (step_x or step_y is ±1) and a fraction along the other, step_mm each.
  float step_x = 1.0f, step_y = 0.0f, step_mm = 1.0f;
  int shadow_steps = 0;
  float elevation = 0.0f;       // radians
  float angular_radius = 0.0f;  // radians, half the light's apparent diameter
  float tan_low = 0.0f;         // tan(elevation − radius), 0 when that is below the plane
  float tan_high = 0.0f;        // tan(elevation + radius), huge at or past the zenith
  // Occlusion: steps along the axes and along the diagonals (√2 cells each).
  int occlusion_steps_axis = 0, occlusion_steps_diagonal = 0;
  float cell_mm = 1.0f;
};

// height_range_mm bounds the difference between any two heights of the canvas: a shadow
// is no longer than the range over tan(elevation − radius), so the march (and the rim an
// update re-shades) stops there, short of settings.shadow_reach_mm on thin paint. Any bound
// gives the same shadows; a tighter one costs less.
ReliefParams relief_params(const RenderSettings& settings, double cell_mm,
                           float height_range_mm = std::numeric_limits<float>::infinity());

// How far (cells) beyond a rectangle of changed heights shading can change: the normals'
// one-cell rim, the occlusion radius all round, and the shadow march downstream of the light.
struct Reach {
  int left = 1, top = 1, right = 1, bottom = 1;
};
Reach reach(const ReliefParams& params);

// The share of the light's disc above a straight horizon at angle `horizon` (radians),
// for a disc of angular radius r centred at `elevation`: 1 below the disc, 0 above it.
inline float visible_disc_share(float horizon, float elevation, float r) {
  const float t = std::clamp((horizon - elevation) / r, -1.0f, 1.0f);
  return (std::acos(t) - t * std::sqrt(1.0f - t * t)) * std::numbers::inv_pi_v<float>;
}

// The share of the light's disc that the relief leaves visible from cell (x, y), whose
// height is h0. max_height bounds every height of the field: the march stops where nothing
// further can raise the horizon (an exact cut, the result does not depend on it).
inline float shadow(const HeightField& field, int x, int y, float max_height,
                    const ReliefParams& p) {
  const float h0 = field.at(x, y);
  float max_tan = 0.0f;
  const bool along_x = std::abs(p.step_x) >= std::abs(p.step_y);
  for (int i = 1; i <= p.shadow_steps; ++i) {
    const float distance = static_cast<float>(i) * p.step_mm;
    if (max_height - h0 <= distance * std::max(max_tan, p.tan_low)) break;
    // One axis lands on a cell; interpolate linearly along the other.
    const float minor = static_cast<float>(along_x ? y : x) +
                        static_cast<float>(i) * (along_x ? p.step_y : p.step_x);
    const float m0 = std::floor(minor);
    const float f = minor - m0;
    const int major = (along_x ? x : y) + i * static_cast<int>(along_x ? p.step_x : p.step_y);
    const int mi = static_cast<int>(m0);
    const float a = along_x ? field.at(major, mi) : field.at(mi, major);
    const float b = along_x ? field.at(major, mi + 1) : field.at(mi + 1, major);
    const float h = a + f * (b - a);
    max_tan = std::max(max_tan, (h - h0) / distance);
    if (max_tan >= p.tan_high) return 0.0f;
  }
  if (max_tan <= 0.0f) return 1.0f;
  return visible_disc_share(std::atan(max_tan), p.elevation, p.angular_radius);
}

// The cosine-weighted share of the sky the relief leaves open above cell (x, y): per
// direction cos² of the horizon angle (1/(1 + tan²)), averaged over the eight directions.
inline float occlusion(const HeightField& field, int x, int y, const ReliefParams& p) {
  constexpr int kDx[kOcclusionDirections] = {1, 1, 0, -1, -1, -1, 0, 1};
  constexpr int kDy[kOcclusionDirections] = {0, 1, 1, 1, 0, -1, -1, -1};
  const float h0 = field.at(x, y);
  float open = 0.0f;
  for (int d = 0; d < kOcclusionDirections; ++d) {
    const bool diagonal = kDx[d] != 0 && kDy[d] != 0;
    const int steps = diagonal ? p.occlusion_steps_diagonal : p.occlusion_steps_axis;
    const float step_mm = diagonal ? p.cell_mm * std::numbers::sqrt2_v<float> : p.cell_mm;
    float max_tan = 0.0f;
    for (int i = 1; i <= steps; ++i) {
      const float h = field.at(x + i * kDx[d], y + i * kDy[d]);
      max_tan = std::max(max_tan, (h - h0) / (static_cast<float>(i) * step_mm));
    }
    open += 1.0f / (1.0f + max_tan * max_tan);
  }
  return open * (1.0f / static_cast<float>(kOcclusionDirections));
}

}  // namespace impasto::render::relief
