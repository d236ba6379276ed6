// The canvas seen from above: K-M colour of the wet layer over the baked dry reflectance at
// the light's quadrature nodes, to XYZ, shaded by the surface normal, to display RGB.
// Assembled after #version, MAX_NODES/MAX_SLOTS defines, km_lib, shading_lib, relief_lib, flakes_lib,
// cracks_lib, crack_close_up_lib, crack_close_up_canvas_lib and the OpenColorIO display
// function `vec4 ocio_display(vec4 xyz)`.

in vec2 uv;
out vec4 frag_color;

uniform sampler2DArray pigments;      // 4 slots a layer, amounts in mm
uniform sampler2D surface;            // r: wet volume (mm), g: total height (mm)
uniform sampler2DArray dry_reflectance;  // 4 nodes a layer, reflectance beneath the wet paint
uniform ivec2 canvas_cells;
uniform mat3 screen_to_cell;          // window pixel (gl_FragCoord) to canvas cell coordinates
uniform vec3 background;              // display RGB outside the canvas

uniform int node_count;
uniform int slot_count;
uniform float slot_absorption[MAX_SLOTS * MAX_NODES];  // [slot * MAX_NODES + node], per optical unit
uniform float slot_scattering[MAX_SLOTS * MAX_NODES];
uniform vec3 node_to_xyz[MAX_NODES];  // display-referred (chromatic adaptation included)
uniform vec3 white_xyz;
uniform float optical_per_mm;  // 1 / RenderSettings::thickness_scale_mm
uniform vec2 saunderson_k;     // (k1, k2); k1 < 0 switches the correction off

uniform vec3 to_light;
uniform float light_intensity;
uniform float ambient;
uniform vec2 dry_material;  // (specular, shininess)
uniform vec2 wet_material;
uniform float inverse_gloss_mm;  // 1 / RenderSettings::wet_gloss_mm
uniform float cell_mm;

float component(vec4 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : i == 2 ? v.z : v.w; }

float total_height(ivec2 cell) {
  return texelFetch(surface, clamp(cell, ivec2(0), canvas_cells - 1), 0).g;
}

void main() {
  vec2 cell_position = (screen_to_cell * vec3(gl_FragCoord.xy, 1.0)).xy;
  ivec2 cell = ivec2(floor(cell_position));
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, canvas_cells))) {
    frag_color = vec4(background, 1.0);
    return;
  }
  vec2 wet = texelFetch(surface, cell, 0).rg;
  float volume = wet.x;

  // Concentration = amount / volume, as the CPU's gather_shares computes it.
  float inverse_volume = volume > 0.0 ? 1.0 / volume : 0.0;
  float concentration[MAX_SLOTS];
  for (int layer = 0; volume > 0.0 && layer * 4 < slot_count; ++layer) {
    vec4 amounts = max(texelFetch(pigments, ivec3(cell, layer), 0), vec4(0.0));
    for (int i = 0; i < 4; ++i) concentration[layer * 4 + i] = component(amounts, i) * inverse_volume;
  }
  float thickness = volume * optical_per_mm;

  // Where there is no wet paint the layer is the identity (R = 0, T = 1 composites to the
  // reflectance below exactly), so bare canvas and dry paint skip the K-M maths, as the CPU
  // reference skips it for wet_volume <= 0.
  bool wet_paint = volume > 0.0;
  vec4 crack = crack_at(cell);
  // Zoomed in over a crack: the close-up needs the cell as if uncracked and the bare ground.
  bool close_up = crack.x > 0.0 && close_up_zoomed(screen_to_cell);
  vec3 xyz_uncracked = vec3(0.0);
  vec3 xyz_ground = vec3(0.0);
  bool saunderson = saunderson_k.x >= 0.0;
  vec3 xyz = vec3(0.0);
  for (int node = 0; node < node_count; ++node) {
    float R = component(texelFetch(dry_reflectance, ivec3(cell, node / 4), 0), node % 4);
    float crack_wall = crack_walls(crack, node, R);
    if (wet_paint) {
      float K = 0.0;
      float S = 0.0;
      for (int slot = 0; slot < slot_count; ++slot) {
        K += concentration[slot] * slot_absorption[slot * MAX_NODES + node];
        S += concentration[slot] * slot_scattering[slot * MAX_NODES + node];
      }
      R = km_composite(km_layer(K, S, thickness), R);
    }
    if (close_up) {
      float ground = crack_ground[node];
      xyz_uncracked += node_to_xyz[node] * (saunderson ? km_saunderson(R, saunderson_k.x, saunderson_k.y) : R);
      xyz_ground += node_to_xyz[node] * (saunderson ? km_saunderson(ground, saunderson_k.x, saunderson_k.y) : ground);
    }
    R = crack_blend(crack, crack_wall, R);
    if (saunderson) R = km_saunderson(R, saunderson_k.x, saunderson_k.y);
    xyz += node_to_xyz[node] * R;
  }

  vec3 normal = shade_height_normal(total_height(cell - ivec2(1, 0)), total_height(cell + ivec2(1, 0)),
                                    total_height(cell - ivec2(0, 1)), total_height(cell + ivec2(0, 1)),
                                    cell_mm);
  vec2 material = shade_blend(dry_material, wet_material, volume * inverse_gloss_mm);
  vec2 shading = shade_blinn_phong(normal, to_light, ambient, material,
                                   relief_visibility(surface, canvas_cells, cell, cell_mm));
  vec3 sparkles = light_intensity * flake_sparkles(cell, normal, total_height(cell));
  vec3 shaded = light_intensity * (xyz * shading.x + white_xyz * shading.y) + sparkles;
  if (close_up) {
    vec3 uncracked = light_intensity * (xyz_uncracked * shading.x + white_xyz * shading.y) + sparkles;
    vec4 inside = crack_close_up_colour(cell, canvas_cells, fract(cell_position), crack, cell_mm,
                                        uncracked, xyz_ground, to_light, ambient, dry_material,
                                        white_xyz, light_intensity);
    shaded = inside.w > 0.0 ? inside.xyz : uncracked;
  }
  frag_color = vec4(ocio_display(vec4(shaded, 1.0)).rgb, 1.0);
}
