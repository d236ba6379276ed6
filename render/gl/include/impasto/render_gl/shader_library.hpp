#pragma once
// The GLSL function libraries, for passes built elsewhere and for tests that check them
// against the CPU reference. Neither has a #version line.

namespace impasto::render_gl {

// fresnel_dielectric, the twin of flakes/fresnel.hpp (optics_lib.glsl; include-guarded, so
// the libraries below that need it may each bring it).
const char* optics_glsl();
// km_one_minus_exp_neg_over_x, km_layer (vec2 R, T), km_composite, km_saunderson.
const char* km_glsl();
// shade_normalized, shade_height_normal, shade_blend, shade_blinn_phong, with the
// constants they share with the C++ (render/shading.hpp) as #defines.
const char* shading_glsl();
// relief_shadow, relief_ambient_occlusion, relief_visibility and their uniforms (after
// shading_glsl), with the constants of render/relief_shading.hpp as #defines.
const char* relief_glsl();
// The flake sparkles (flakes_lib.glsl, after optics_glsl) with MAX_FLAKES and the flake table sizes
// as #defines from FlakeTextures and flakes::FlakeTables (needs MAX_NODES).
const char* flakes_glsl();
// The crack shading (cracks_lib.glsl) with CRACK_SHAPES from paintcore::kCrackShapeCount.
const char* cracks_glsl();

}  // namespace impasto::render_gl
