#include "impasto/render/render_settings.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::render {
namespace {

void require(bool ok, const char* field, double value, const char* expected) {
  if (!ok) {
    throw std::runtime_error(std::string("render settings: ") + field + " = " +
                             std::to_string(value) + " (expected " + expected + ")");
  }
}

}  // namespace

void validate(const RenderSettings& s) {
  require(s.wavelengths >= 0 && s.wavelengths <= kMaxNodes, "wavelengths", s.wavelengths,
          "1..16, or 0 for the full spectrum");
  require(std::isfinite(s.thickness_scale_mm) && s.thickness_scale_mm > 0.0, "thickness_scale_mm",
          s.thickness_scale_mm, "> 0");
  require(std::isfinite(s.light_azimuth_deg), "light_azimuth_deg", s.light_azimuth_deg,
          "a finite angle");
  require(s.light_elevation_deg > 0.0 && s.light_elevation_deg <= 90.0, "light_elevation_deg",
          s.light_elevation_deg, "in (0, 90]");
  require(s.ambient >= 0.0 && s.ambient <= 1.0, "ambient", s.ambient, "in [0, 1]");
  require(s.wet_gloss_mm > 0.0 && std::isfinite(s.wet_gloss_mm), "wet_gloss_mm", s.wet_gloss_mm,
          "> 0");
  require(data::saunderson_coefficient_valid(s.saunderson_k1), "saunderson_k1", s.saunderson_k1,
          data::kSaundersonCoefficientRange);
  require(data::saunderson_coefficient_valid(s.saunderson_k2), "saunderson_k2", s.saunderson_k2,
          data::kSaundersonCoefficientRange);
  for (const auto* m : {&s.dry_material, &s.wet_material}) {
    require(m->specular >= 0.0f && m->specular <= 1.0f, "material specular", m->specular,
            "in [0, 1]");
    require(m->shininess >= 1.0f && m->shininess <= 10000.0f, "material shininess", m->shininess,
            "in [1, 10000]");
  }
  require(s.shadow_light_diameter_deg > 0.0 && s.shadow_light_diameter_deg <= 90.0,
          "shadow_light_diameter_deg", s.shadow_light_diameter_deg, "in (0, 90]");
  require(s.shadow_reach_mm >= 0.0 && s.shadow_reach_mm <= 1000.0, "shadow_reach_mm",
          s.shadow_reach_mm, "in [0, 1000]");
  require(s.occlusion_radius_mm >= 0.0 && s.occlusion_radius_mm <= 100.0, "occlusion_radius_mm",
          s.occlusion_radius_mm, "in [0, 100]");
  require(s.threads >= 0 && s.threads <= 1024, "threads", s.threads, "0..1024");
  require(s.light_size_deg > 0.0 && s.light_size_deg <= 90.0, "light_size_deg", s.light_size_deg,
          "in (0, 90]");
  require(s.light_distance_mm > 0.0 && s.light_distance_mm <= 1e7, "light_distance_mm",
          s.light_distance_mm, "in (0, 1e7]");
  require(s.spot_angle_deg > 0.0 && s.spot_angle_deg < 90.0, "spot_angle_deg", s.spot_angle_deg,
          "in (0, 90)");
  validate(s.surface);
}

ReflectanceStorage parse_reflectance_storage(std::string_view text) {
  return util::parse_name(kReflectanceStorageNames, text, "reflectance storage");
}

LightType parse_light_type(std::string_view text) {
  return util::parse_name(kLightTypeNames, text, "light type");
}

CrackModel parse_crack_model(std::string_view text) {
  return util::parse_name(cracks::kCavityModelNames, text, "crack model");
}

}  // namespace impasto::render
