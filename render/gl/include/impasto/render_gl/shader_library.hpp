#pragma once
// The GLSL function libraries, for passes built elsewhere and for tests that check them
// against the CPU reference. Neither has a #version line.

namespace impasto::render_gl {

// km_one_minus_exp_neg_over_x, km_layer (vec2 R, T), km_composite, km_saunderson.
const char* km_glsl();
// shade_normalized, shade_height_normal, shade_blend, shade_blinn_phong.
const char* shading_glsl();

}  // namespace impasto::render_gl
