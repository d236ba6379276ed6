#include "impasto/render/shading_key.hpp"

namespace impasto::render {

std::vector<double> shading_settings_key(const RenderSettings& s) {
  return {s.light_azimuth_deg,
          s.light_elevation_deg,
          s.ambient,
          s.dry_material.specular,
          s.dry_material.shininess,
          s.wet_material.specular,
          s.wet_material.shininess,
          s.wet_gloss_mm,
          s.shadows ? 1.0 : 0.0,
          s.occlusion ? 1.0 : 0.0,
          s.shadow_light_diameter_deg,
          s.shadow_reach_mm,
          s.occlusion_radius_mm};
}

}  // namespace impasto::render
