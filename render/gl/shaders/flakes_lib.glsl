// Sparkles of flake paint: a port of the CPU reference in optics/flakes (counter_rng.hpp,
// sparkle_count.cpp, sparkle_math.hpp, fresnel.hpp, sparkles.cpp) and of the renderer hook
// render/src/flake_shading.cpp, line by line, in float. Needs MAX_NODES; MAX_FLAKES (flake
// pigments one canvas can hold on the GPU), FLAKE_ORIENTATION_SAMPLES and FLAKE_ANGLE_SAMPLES
// (the table sizes) are #defined from the C++ by flakes_glsl() (shader_library.cpp).

uniform int flake_count;              // flake pigments on the canvas; 0: no sparkles at all
uniform sampler2D flake_layer;        // per cell: top layer thickness (mm), 3 concentrations
uniform sampler2D flake_tables;       // R32F, FLAKE_ROWS rows per flake pigment (see below)
uniform vec4 flake_paint[MAX_FLAKES];   // D<S> (mm^2/mm^3), <S> (mm^2), eta, kappa (1/mm)
uniform vec4 flake_paint2[MAX_FLAKES];  // c1 (1/mm), mean and deviation of ln S, deviation of S
uniform int flake_light_kind;         // 0 directional, 1 point, 2 spot
uniform vec3 flake_light_direction;   // directional, spot: the way the light travels
uniform vec3 flake_light_position;    // point, spot (mm)
uniform float flake_light_diameter;   // apparent diameter, radians
uniform vec2 flake_spot_cos;          // cos of the outer and inner half-angles
uniform float flake_light_strength;   // per node: irradiance normal to the beam (or intensity)
uniform float flake_orientation_cell;
uniform uint flake_seed;
uniform bool flake_masking;
uniform int flake_nodes;                   // wavelength nodes
uniform vec3 flake_node_to_xyz[MAX_NODES];  // display-referred XYZ per unit node radiance
uniform float flake_cell_mm;

// Rows of flake_tables per pigment: P at sin(beta/2) = i*max/(FLAKE_ORIENTATION_SAMPLES - 1), <s> and
// <t_p> at cos theta = i/(FLAKE_ANGLE_SAMPLES - 1),
// then r_p at cos alpha = i/(FLAKE_ANGLE_SAMPLES - 1) for each node.
const int FLAKE_ROWS = 3 + MAX_NODES;
const float FLAKE_MAX_HALF_SIN = 0.70710678118654752;
const float FLAKE_PI = 3.14159265358979324;

float flake_table(int pigment, int row, int samples, float x, float x_max) {
  int r = pigment * FLAKE_ROWS + row;
  float last = float(samples - 1);
  float u = x / x_max * last;
  if (!(u > 0.0)) return texelFetch(flake_tables, ivec2(0, r), 0).r;
  if (u >= last) return texelFetch(flake_tables, ivec2(samples - 1, r), 0).r;
  int i = int(u);
  float f = u - float(i);
  float a = texelFetch(flake_tables, ivec2(i, r), 0).r;
  float b = texelFetch(flake_tables, ivec2(i + 1, r), 0).r;
  return a + f * (b - a);
}

float flake_orientation_density(int pigment, float cos_beta) {
  float half_sin = sqrt(max(0.0, 0.5 * (1.0 - cos_beta)));
  if (half_sin > FLAKE_MAX_HALF_SIN) return 0.0;
  return flake_table(pigment, 0, FLAKE_ORIENTATION_SAMPLES, half_sin, FLAKE_MAX_HALF_SIN);
}

// --- counter-based random numbers (pcg4d) ---

uvec4 flake_pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

struct FlakeRng {
  uvec4 first;
  uvec4 block;
  uint counter;
  int used;
};

FlakeRng flake_rng(uvec4 key) {
  uvec4 first = flake_pcg4d(key);
  return FlakeRng(first, first, 0u, 0);
}

float flake_uniform(inout FlakeRng rng) {
  if (rng.used == 4) {
    rng.counter += 1u;
    rng.block = flake_pcg4d(uvec4(rng.first.x + rng.counter, rng.first.yzw));
    rng.used = 0;
  }
  uint u = rng.block[rng.used];
  rng.used += 1;
  return (float(u) + 0.5) * exp2(-32.0);
}

float flake_normal(inout FlakeRng rng) {
  float u1 = flake_uniform(rng);
  float u2 = flake_uniform(rng);
  return sqrt(-2.0 * log(u1)) * cos(2.0 * FLAKE_PI * u2);
}

// ln k! (Stirling's series past 8, exact sums below).
float flake_log_factorial(float k) {
  if (k < 8.0) {
    float sum = 0.0;
    for (float i = 2.0; i <= k; i += 1.0) sum += log(i);
    return sum;
  }
  float x = k + 1.0;
  return (x - 0.5) * log(x) - x + 0.91893853320467274 + 1.0 / (12.0 * x) -
         1.0 / (360.0 * x * x * x);
}

int flake_sparkle_count(inout FlakeRng rng, float mean) {
  if (!(mean > 0.0)) return 0;
  if (mean < 0.1) return flake_uniform(rng) <= mean ? 1 : 0;
  if (mean < 10.0) {
    float p = exp(-mean);
    float cdf = p;
    float u = flake_uniform(rng);
    int k = 0;
    while (u > cdf && k < 1000) {
      ++k;
      p *= mean / float(k);
      cdf += p;
    }
    return k;
  }
  if (mean > 1e9) return int(round(min(mean, 2e9)));
  // Hoermann's PTRS.
  float slam = sqrt(mean);
  float loglam = log(mean);
  float b = 0.931 + 2.53 * slam;
  float a = -0.059 + 0.02483 * b;
  float inv_alpha = 1.1239 + 1.1328 / (b - 3.4);
  float vr = 0.9277 - 3.6224 / (b - 2.0);
  for (int tries = 0; tries < 64; ++tries) {
    float u = flake_uniform(rng) - 0.5;
    float v = flake_uniform(rng);
    float us = 0.5 - abs(u);
    float k = floor((2.0 * a / us + b) * u + mean + 0.43);
    if (us >= 0.07 && v <= vr) return int(k);
    if (k < 0.0 || (us < 0.013 && v > us)) continue;
    if (log(v) + log(inv_alpha) - log(a / (us * us) + b) <=
        -mean + k * loglam - flake_log_factorial(k)) {
      return int(k);
    }
  }
  return int(round(mean));
}

// --- optics (sparkle_math.hpp, fresnel.hpp) ---

vec3 flake_refract_into_binder(vec3 V, vec3 n, float eta) {
  float cos_out = dot(n, V);
  float sin2_out = 1.0 - cos_out * cos_out;
  float cos_in = sqrt(max(0.0, eta * eta - sin2_out)) / eta;
  return (1.0 / eta) * V + (cos_in - cos_out / eta) * n;
}

float flake_cos_inside_binder(float cos_out, float eta) {
  float sin2_out = 1.0 - cos_out * cos_out;
  return sqrt(max(0.0, 1.0 - sin2_out / (eta * eta)));
}

float flake_direct_fraction(float t_per_depth, float depth) {
  float x = t_per_depth * depth;
  if (x < 1e-6) return 1.0 - 0.5 * x;
  // -expm1(-x) / x; for small x, 1 - e^{-x} loses digits in float, so a series below 1e-2.
  if (x < 1e-2) return 1.0 - x * (0.5 - x * (1.0 / 6.0 - x / 24.0));
  return (1.0 - exp(-x)) / x;
}

float flake_optical_thickness(int f, float concentration, float cos_in) {
  vec4 p = flake_paint[f];
  float tau = concentration * p.x *
                  (flake_table(f, 1, FLAKE_ANGLE_SAMPLES, cos_in, 1.0) - flake_table(f, 2, FLAKE_ANGLE_SAMPLES, cos_in, 1.0)) +
              p.w + 16.0 * FLAKE_PI / 3.0 * concentration * flake_paint2[f].x;
  return tau / cos_in;
}

uint flake_orientation_cell_index(float slope) {
  float q = clamp(floor(slope / flake_orientation_cell), -1e9, 1e9);
  return uint(int(q));
}

// Adds the sparkle radiance of flake pigment f in one cell, per node, to `radiance`; returns
// the number of sparkles (sparkles.cpp: prepare, add_cell).
int flake_cell(int f, ivec2 cell, vec3 n, float height, float concentration, float thickness,
               inout float radiance[MAX_NODES]) {
  vec3 center = vec3((vec2(cell) + 0.5) * flake_cell_mm, height);
  vec3 to_light;
  float beam = 1.0;
  if (flake_light_kind == 0) {
    to_light = -normalize(flake_light_direction);
  } else {
    vec3 d = flake_light_position - center;
    float distance2 = dot(d, d);
    to_light = (1.0 / sqrt(distance2)) * d;
    beam = 1.0 / distance2;
    if (flake_light_kind == 2) {
      beam *= smoothstep(flake_spot_cos.x, flake_spot_cos.y,
                         -dot(normalize(flake_light_direction), to_light));
    }
  }
  if (!(n.z > 0.0)) return 0;
  float cos_light = dot(n, to_light);
  float cos_view = n.z;
  if (!(beam > 0.0) || !(cos_light > 0.0) || !(cos_view > 0.0)) return 0;

  float eta = flake_paint[f].z;
  vec3 v_light = flake_refract_into_binder(to_light, n, eta);
  vec3 v_view = flake_refract_into_binder(vec3(0.0, 0.0, 1.0), n, eta);
  float cos_light_in = flake_cos_inside_binder(cos_light, eta);
  float cos_view_in = flake_cos_inside_binder(cos_view, eta);
  vec3 nf = normalize(v_view + v_light);
  float cos_alpha = dot(nf, v_light);
  float density = flake_orientation_density(f, dot(nf, n));
  if (!(density > 0.0)) return 0;

  float delta_in = 0.5 * flake_light_diameter / eta * sqrt(cos_light / cos_light_in);
  float depth = thickness * n.z;
  float area = flake_cell_mm * flake_cell_mm;
  float flakes = concentration * flake_paint[f].x / flake_paint[f].y * area * thickness;
  float probability = density * delta_in * delta_in / (8.0 * cos_alpha);
  float t = flake_optical_thickness(f, concentration, cos_light_in) +
            flake_optical_thickness(f, concentration, cos_view_in);
  float mean_count = flake_masking ? flakes * probability
                                   : flake_direct_fraction(t, depth) * flakes * probability;
  if (!(mean_count > 0.0)) return 0;

  uvec4 key = uvec4(uint(cell.x), uint(cell.y), flake_orientation_cell_index(nf.x / nf.z),
                    flake_orientation_cell_index(nf.y / nf.z) ^ (flake_seed * 0x9E3779B9u));
  FlakeRng rng = flake_rng(key);
  int count = flake_sparkle_count(rng, mean_count);
  if (count == 0) return 0;

  // sum S*exp(-tz) over the sparkles.
  vec4 p2 = flake_paint2[f];
  float weight = 0.0;
  if (count > 256) {
    float mean_s = flake_paint[f].y, sd_s = p2.w;
    float a1 = flake_masking ? flake_direct_fraction(t, depth) : 1.0;
    float a2 = flake_masking ? flake_direct_fraction(2.0 * t, depth) : 1.0;
    float mean = mean_s * a1;
    float variance = max(0.0, (sd_s * sd_s + mean_s * mean_s) * a2 - mean * mean);
    weight = max(0.0, float(count) * mean + sqrt(float(count) * variance) * flake_normal(rng));
  } else {
    for (int i = 0; i < count; ++i) {
      float s = p2.z > 0.0 ? exp(p2.y + p2.z * flake_normal(rng)) : flake_paint[f].y;
      weight += flake_masking ? s * exp(-t * depth * flake_uniform(rng)) : s;
    }
  }

  float energy = beam * cos_light / cos_light_in * (1.0 - fresnel_dielectric(cos_light, eta)) *
                 (1.0 - fresnel_dielectric(cos_view, eta)) * cos_alpha;
  float surface_area = area / n.z;
  float per_area = energy / (FLAKE_PI * delta_in * delta_in * eta * eta * cos_view_in * surface_area);
  float scale = per_area * weight * flake_light_strength;
  for (int node = 0; node < flake_nodes; ++node) {
    radiance[node] += scale * flake_table(f, 3 + node, FLAKE_ANGLE_SAMPLES, cos_alpha, 1.0);
  }
  return count;
}

// The sparkles of every flake pigment in a cell's top layer, as display-referred XYZ.
vec3 flake_sparkles(ivec2 cell, vec3 normal, float height) {
  if (flake_count == 0) return vec3(0.0);
  vec4 layer = texelFetch(flake_layer, cell, 0);
  if (!(layer.x > 0.0)) return vec3(0.0);
  float radiance[MAX_NODES];
  for (int node = 0; node < MAX_NODES; ++node) radiance[node] = 0.0;
  int sparkles = 0;
  for (int f = 0; f < flake_count; ++f) {
    float concentration = f == 0 ? layer.y : f == 1 ? layer.z : layer.w;
    if (concentration > 0.0) {
      sparkles += flake_cell(f, cell, normal, height, concentration, layer.x, radiance);
    }
  }
  vec3 xyz = vec3(0.0);
  if (sparkles > 0) {
    for (int node = 0; node < flake_nodes; ++node) xyz += flake_node_to_xyz[node] * radiance[node];
  }
  return xyz;
}
