#include "impasto/render/relief_shading.hpp"

#include <limits>

#include "impasto/render/render_settings.hpp"

namespace impasto::render::relief {

ReliefParams relief_params(const RenderSettings& settings, double cell_mm, float height_range_mm) {
  constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
  ReliefParams p;
  p.shadows = settings.shadows;
  p.occlusion = settings.occlusion;
  p.cell_mm = static_cast<float>(cell_mm);

  const double azimuth = settings.light_azimuth_deg * kRadiansPerDegree;
  const double dx = std::cos(azimuth), dy = std::sin(azimuth);
  const double dominant = std::max(std::abs(dx), std::abs(dy));
  // The dominant axis moves exactly one cell a step.
  p.step_x =
      std::abs(dx) >= std::abs(dy) ? (dx > 0.0 ? 1.0f : -1.0f) : static_cast<float>(dx / dominant);
  p.step_y =
      std::abs(dx) >= std::abs(dy) ? static_cast<float>(dy / dominant) : (dy > 0.0 ? 1.0f : -1.0f);
  p.step_mm = static_cast<float>(cell_mm / dominant);
  p.shadow_steps =
      settings.shadows ? static_cast<int>(std::floor(settings.shadow_reach_mm / p.step_mm)) : 0;

  const double elevation = settings.light_elevation_deg * kRadiansPerDegree;
  const double radius = 0.5 * settings.shadow_light_diameter_deg * kRadiansPerDegree;
  p.elevation = static_cast<float>(elevation);
  p.angular_radius = static_cast<float>(radius);
  p.tan_low = elevation - radius > 0.0 ? static_cast<float>(std::tan(elevation - radius)) : 0.0f;
  p.tan_high = elevation + radius < 0.5 * std::numbers::pi
                   ? static_cast<float>(std::tan(elevation + radius))
                   : std::numeric_limits<float>::max();
  // Past range / tan_low nothing can rise above the disc's lower edge: shadow() would cut
  // its march there anyway.
  if (p.tan_low > 0.0f && std::isfinite(height_range_mm)) {
    const double longest = std::max(0.0f, height_range_mm) / (p.tan_low * p.step_mm);
    // Two steps beyond it, so float rounding of the cut cannot end the march early.
    if (longest + 2.0 < p.shadow_steps) p.shadow_steps = static_cast<int>(longest) + 2;
  }

  if (settings.occlusion) {
    p.occlusion_steps_axis = static_cast<int>(std::lround(settings.occlusion_radius_mm / cell_mm));
    p.occlusion_steps_diagonal = static_cast<int>(
        std::lround(settings.occlusion_radius_mm / (cell_mm * std::numbers::sqrt2)));
  }
  return p;
}

Reach reach(const ReliefParams& p) {
  const int around = std::max({1, p.occlusion_steps_axis, p.occlusion_steps_diagonal});
  Reach r{around, around, around, around};
  if (p.shadows && p.shadow_steps > 0) {
    // A cell reads the heights up to shadow_steps steps toward the light, and one cell
    // beside its path (the interpolation), so changed heights shade cells downstream.
    const auto far = [&](float step) {
      return static_cast<int>(
                 std::ceil(static_cast<float>(p.shadow_steps) * std::max(step, 0.0f))) +
             1;
    };
    r.left = std::max(r.left, far(p.step_x));
    r.right = std::max(r.right, far(-p.step_x));
    r.top = std::max(r.top, far(p.step_y));
    r.bottom = std::max(r.bottom, far(-p.step_y));
  }
  return r;
}

}  // namespace impasto::render::relief
