#pragma once
// What in the render settings changes a cell's shading factors (the light's direction, the
// ambient share, the materials and gloss, the relief's shadows and occlusion), as numbers to
// compare: the CPU renderer's relight (TileRenderer) reuses its cached factors, and the
// window's cached view (render_gl::ShadedViewCache) its image, only while it is unchanged.
// A setting that changes the shading goes here, once, so that neither cache keeps a stale one
// (tests/render/shading_key_test.cpp changes each).
#include <vector>

#include "impasto/render/render_settings.hpp"

namespace impasto::render {

// Calls visit(&RenderSettings::member) for each setting that changes the shading factors:
// the one list, which the key and the copy below read.
template <class Visit>
void for_each_shading_setting(Visit&& visit) {
  visit(&RenderSettings::light_azimuth_deg);
  visit(&RenderSettings::light_elevation_deg);
  visit(&RenderSettings::ambient);
  visit(&RenderSettings::dry_material);
  visit(&RenderSettings::wet_material);
  visit(&RenderSettings::wet_gloss_mm);
  visit(&RenderSettings::shadows);
  visit(&RenderSettings::occlusion);
  visit(&RenderSettings::shadow_light_diameter_deg);
  visit(&RenderSettings::shadow_reach_mm);
  visit(&RenderSettings::occlusion_radius_mm);
  // The sky's reflection in the paint's surface (k1 when on; shade::blinn_phong).
  visit(&RenderSettings::saunderson);
  visit(&RenderSettings::saunderson_k1);
}

// The colour settings the window's shader reads as uniforms, which it takes with the shading
// (render_gl::CanvasRenderer::set_shading) rather than with a new palette: the Saunderson
// interface (also in the list above: the sky's reflection) and the crack correction.
template <class Visit>
void for_each_shader_colour_setting(Visit&& visit) {
  visit(&RenderSettings::saunderson);
  visit(&RenderSettings::saunderson_k1);
  visit(&RenderSettings::saunderson_k2);
  visit(&RenderSettings::cracks);
  visit(&RenderSettings::crack_model);
}

std::vector<double> shading_settings_key(const RenderSettings& settings);
// The settings of for_each_shader_colour_setting as numbers to compare.
std::vector<double> shader_colour_settings_key(const RenderSettings& settings);

// Copies the settings of both lists above from `from` into `to`, leaving the rest of `to`.
void copy_shading_settings(const RenderSettings& from, RenderSettings& to);

}  // namespace impasto::render
