// The ghs surface model: a port of render/src/surface_brdf.cpp (the GHS kernel, Fresnel, the
// renormalised, shadowed BRDF and its multiply scattered lobe) and of render::SurfaceShading::shade (render/src/surface_shading.cpp),
// the CPU reference it is tested against (tests/gl/ghs_surface_test.cpp). docs/surface.md
// derives the terms.
// Needs MAX_NODES, SHADE_OCCLUSION_DIRECT_SHARE (shading_lib), and from the C++
// (GhsSurfaceTables): GHS_TABLE_SIZE (surface::GhsBrdf::kTableSize), GHS_BLOCKS (the
// surfaces: the settings' dry one, the wet one, the levels of paint and varnish) and
// GHS_WET_BLOCK, GHS_SECOND_TABLE (the column of the second table).

uniform bool ghs_enabled;     // SurfaceSettings::model == ghs; else Blinn-Phong
uniform bool ghs_reflection;  // SurfaceSettings::reflection
// Row = a surface (block), layer = a node. Columns 0..GHS_TABLE_SIZE-1 at cos θ =
// i / (GHS_TABLE_SIZE - 1): (renormalisation, directional albedo), as GhsBrdf tabulates them;
// then (index, hemispherical albedo); then (RMS height, correlation length) in µm; then from
// GHS_SECOND_TABLE, at the same cosines: (Smith's shadowing, the multiply scattered lobe's
// factor).
uniform sampler2DArray ghs_tables;
// Per cell: (the block of its dry surface, its least wetness: a varnish not yet dry); absent
// (ghs_cells_present false) while the painting has no media or varnish of its own.
uniform sampler2D ghs_cells;
uniform bool ghs_cells_present;
uniform float ghs_wavelength_nm[MAX_NODES];
uniform vec2 ghs_reference[MAX_NODES];  // (t0(flat light)·t0(view), t̄0·t0(view)): the body's divisors
uniform float ghs_source_sigma;         // the light's disc in direction cosines
uniform float ghs_subcell_slope;        // SurfaceSettings::subcell_slope_rms

const float GHS_PI = 3.14159265358979;
// Above this phase variance the Poisson mixture is summed as m ~ Normal(g, g) by a 9-point
// Gauss–Hermite rule, as surface_brdf.cpp does (tests/gl/ghs_surface_test.cpp checks the
// kernel on both sides of it against the C++).
const float GHS_POISSON_NORMAL_FROM = 25.0;
const float GHS_HERMITE_NODES[5] =
    float[5](0.0, 0.7235510187528376, 1.468553289216668, 2.266580584531843, 3.190993201781528);
const float GHS_HERMITE_WEIGHTS[5] = float[5](0.7202352156060510, 0.4326515590025558,
                                              0.08847452739437657, 0.004943624275536947,
                                              0.00003960697726326438);

// A cell's dry surface (SurfaceShading::cell_dry): its block and least wetness.
vec2 ghs_cell_dry(ivec2 cell) {
  return ghs_cells_present ? texelFetch(ghs_cells, cell, 0).rg : vec2(0.0);
}

float ghs_gaussian_2d(float rho2, float variance) {
  return exp(-rho2 / (2.0 * variance)) / (2.0 * GHS_PI * variance);
}

// surface::ghs_kernel: Σ_m e^(−g) g^m/m! N(ρ; s_m² + source² + sub-cell slopes).
float ghs_kernel(vec2 roughness, float wavelength_nm, float source_sigma, float subcell_slope,
                 float cos_i, float cos_o, float rho) {
  float lambda_um = wavelength_nm * 1e-3;
  float phase = 2.0 * GHS_PI * roughness.x / lambda_um * (cos_i + cos_o);
  float g = phase * phase;
  float l_hat = roughness.y / lambda_um;
  float per_m = 1.0 / (2.0 * GHS_PI * GHS_PI * l_hat * l_hat);
  float tilt = (cos_i + cos_o) * subcell_slope;
  float source2 = source_sigma * source_sigma + tilt * tilt;
  float rho2 = rho * rho;
  if (g <= GHS_POISSON_NORMAL_FROM) {
    // Term by term; the C++ stops once what is left of the Poisson mass is below 1e-9 and
    // skips terms lighter than that: past the mode (m > g) the weights only fall, so the
    // first one below 1e-9 there ends the same sum.
    float weight = exp(-g);
    float sum = weight * ghs_gaussian_2d(rho2, source2);
    for (int m = 1; m < 200; ++m) {
      weight *= g / float(m);
      if (weight <= 1e-9) {
        if (float(m) > g) break;
        continue;
      }
      sum += weight * ghs_gaussian_2d(rho2, per_m * float(m) + source2);
    }
    return sum;
  }
  float spread = sqrt(2.0 * g);
  float sum = GHS_HERMITE_WEIGHTS[0] * ghs_gaussian_2d(rho2, per_m * g + source2);
  for (int k = 1; k < 5; ++k) {
    for (int side = 0; side < 2; ++side) {
      float m = g + (side == 0 ? -1.0 : 1.0) * spread * GHS_HERMITE_NODES[k];
      sum += GHS_HERMITE_WEIGHTS[k] * ghs_gaussian_2d(rho2, per_m * m + source2);
    }
  }
  return sum / sqrt(GHS_PI);
}

// GhsBrdf's tables at cos_i, interpolated as table_lookup does: (renormalisation, albedo).
vec2 ghs_table_at(int column, int block, int node, float cos_i) {
  float u = clamp(cos_i, 0.0, 1.0) * float(GHS_TABLE_SIZE - 1);
  int k = min(int(u), GHS_TABLE_SIZE - 2);
  float f = u - float(k);
  vec2 a = texelFetch(ghs_tables, ivec3(column + k, block, node), 0).rg;
  vec2 b = texelFetch(ghs_tables, ivec3(column + k + 1, block, node), 0).rg;
  return a * (1.0 - f) + b * f;
}
vec2 ghs_table(int block, int node, float cos_i) { return ghs_table_at(0, block, node, cos_i); }

// (index, hemispherical albedo) of a surface at a node.
vec2 ghs_optics(int block, int node) {
  return texelFetch(ghs_tables, ivec3(GHS_TABLE_SIZE, block, node), 0).rg;
}

// GhsBrdf::eval of one surface at one node.
float ghs_brdf(int block, int node, float cos_i, float cos_o, float rho, float cos_half) {
  if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
  float renorm = min(ghs_table(block, node, cos_i).x, ghs_table(block, node, cos_o).x);
  // (shadowing, multiply scattered factor) of each direction.
  vec2 in_second = ghs_table_at(GHS_SECOND_TABLE, block, node, cos_i);
  vec2 out_second = ghs_table_at(GHS_SECOND_TABLE, block, node, cos_o);
  vec2 roughness = texelFetch(ghs_tables, ivec3(GHS_TABLE_SIZE + 1, block, node), 0).rg;
  return fresnel_dielectric(cos_half, ghs_optics(block, node).x) * renorm * in_second.x *
             out_second.x *
             ghs_kernel(roughness, ghs_wavelength_nm[node], ghs_source_sigma, ghs_subcell_slope,
                        cos_i, cos_o, rho) +
         in_second.y * out_second.y;
}

float ghs_mix(float dry, float wet, float w) { return dry + w * (wet - dry); }

// SurfaceShading::shade without the K-M reflectance, for `nodes` nodes: per node, what
// multiplies the reflectance (body) and the surface's own light (surface_light), so that the
// cell's colour is Σ node_to_xyz·(R·body + surface_light). Viewer straight above;
// visibility = (shadow, occlusion).
void ghs_shade(ivec2 cell, int nodes, vec3 normal, vec3 to_light, float ambient, vec2 visibility,
               float wetness, out float body[MAX_NODES], out float surface_light[MAX_NODES]) {
  vec2 cell_dry = ghs_cell_dry(cell);
  int dry = int(cell_dry.x + 0.5);
  float w = min(max(wetness > 0.0 ? wetness : 0.0, cell_dry.y), 1.0);  // NaN: dry
  float mu_i = dot(normal, to_light);
  float mu_v = normal.z;
  float flat_lambert = max(to_light.z, 0.05);
  float lit = max(mu_i, 0.0);
  float direct = visibility.x * (1.0 - SHADE_OCCLUSION_DIRECT_SHARE * (1.0 - visibility.y));
  // The half-way geometry: |tangential part of l + v| and the Fresnel angle's cosine.
  vec3 sum = vec3(to_light.xy, to_light.z + 1.0);
  float sum2 = dot(sum, sum);
  float along = dot(normal, sum);
  float rho = sqrt(max(0.0, sum2 - along * along));
  float cos_half = (1.0 + to_light.z) / sqrt(sum2);
  float sky = ambient * visibility.y;
  float sun = 1.0 - ambient;
  for (int node = 0; node < nodes; ++node) {
    float albedo_in = mu_i > 0.0 ? ghs_mix(ghs_table(dry, node, mu_i).y,
                                           ghs_table(GHS_WET_BLOCK, node, mu_i).y, w)
                                 : 0.0;
    float albedo_view =
        ghs_mix(ghs_table(dry, node, mu_v).y, ghs_table(GHS_WET_BLOCK, node, mu_v).y, w);
    float albedo_sky =
        ghs_mix(ghs_optics(dry, node).y, ghs_optics(GHS_WET_BLOCK, node).y, w);
    float exit_share = 1.0 - albedo_view;
    body[node] = sky * (1.0 - albedo_sky) * exit_share / ghs_reference[node].y +
                 sun * (lit / flat_lambert) * direct * (1.0 - albedo_in) * exit_share /
                     ghs_reference[node].x;
    surface_light[node] = 0.0;
    if (ghs_reflection) {
      // The dry and the wet surface in one loop (one copy of the kernel in the compiled
      // shader), each skipped where it has no weight.
      float f_surface[2] = float[2](0.0, 0.0);
      for (int s = 0; mu_i > 0.0 && s < 2; ++s) {
        if (s == 0 ? w < 1.0 : w > 0.0) {
          f_surface[s] = ghs_brdf(s == 0 ? dry : GHS_WET_BLOCK, node, mu_i, mu_v, rho, cos_half);
        }
      }
      float f = ghs_mix(f_surface[0], f_surface[1], w);
      // π f cos θ_i against the white Lambertian's cos θ_flat: the units of the body above.
      surface_light[node] = sun * visibility.x * GHS_PI * f * lit / flat_lambert + sky * albedo_view;
    }
  }
}
