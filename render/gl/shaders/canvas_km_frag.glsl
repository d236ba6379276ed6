// The canvas seen from above: K-M colour of the wet layer over the baked dry reflectance at
// the light's quadrature nodes, to XYZ, shaded by the surface normal and the light the
// relief lets through, to display RGB. At one pixel a cell (and with smooth_zoom off) each
// pixel shows its cell as the CPU reference renders it; zoomed in, colour, normal and relief
// light are interpolated between cell centres; zoomed out, the shaded colours of the cells
// under the pixel are averaged.
// With the ghs surface model (surface_ghs_lib) the rough surface per node replaces
// Blinn-Phong: the K-M reflectance of each node is weighted by the light the surface lets
// through, and the surface's own light is added per node.
// Assembled after #version, MAX_NODES/MAX_SLOTS defines, km_lib, shading_lib, surface_ghs_lib,
// relief_lib, flakes_lib, cracks_lib, crack_close_up_lib, crack_close_up_canvas_lib, the
// OpenColorIO display function `vec4 ocio_display(vec4 xyz)`, subsurface_canvas_lib (each
// cell's light with the subsurface spread; the output's encoding) and tile_atlas_lib.

in vec2 uv;
out vec4 frag_color;

// The tiles with paint or dry layers, in a TileAtlas: 4 slots a layer, amounts in mm, then
// from dry_first_layer 4 nodes a layer, the reflectance beneath the wet paint. A tile with no
// place holds no pigment over the bare ground (bare_reflectance).
uniform sampler2DArray tile_data;
uniform int dry_first_layer;
uniform float bare_reflectance[MAX_NODES];
uniform sampler2D surface;            // r: wet volume (mm), g: total height (mm)
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
uniform bool smooth_zoom;  // GpuViewOptions::smooth_zoom

float component(vec4 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : i == 2 ? v.z : v.w; }

float total_height(ivec2 cell) {
  return texelFetch(surface, clamp(cell, ivec2(0), canvas_cells - 1), 0).g;
}

// A cell's K-M colour (display XYZ, before shading): the wet layer of `volume` mm over the
// dry reflectance, the crack's far-view blend in, each node's reflectance weighted by
// body[node] (1 for Blinn-Phong; the ghs model's body light). With close_up, also the colour
// as if uncracked and the bare ground's (unweighted), which the close-up draws.
vec3 cell_xyz(ivec2 cell, float volume, vec4 crack, bool close_up, float body[MAX_NODES],
              out vec3 xyz_uncracked, out vec3 xyz_ground) {
  // Concentration = amount / volume, as the CPU's gather_shares computes it.
  float inverse_volume = volume > 0.0 ? 1.0 / volume : 0.0;
  ivec2 texel = atlas_texel(cell);
  bool bare = texel.x < 0;  // wet paint has a tile, so a place: bare cells have no volume
  float concentration[MAX_SLOTS];
  for (int layer = 0; volume > 0.0 && !bare && layer * 4 < slot_count; ++layer) {
    vec4 amounts = max(texelFetch(tile_data, ivec3(texel, layer), 0), vec4(0.0));
    for (int i = 0; i < 4; ++i) concentration[layer * 4 + i] = component(amounts, i) * inverse_volume;
  }
  float thickness = volume * optical_per_mm;

  // Where there is no wet paint the layer is the identity (R = 0, T = 1 composites to the
  // reflectance below exactly), so bare canvas and dry paint skip the K-M maths, as the CPU
  // reference skips it for wet_volume <= 0.
  bool wet_paint = volume > 0.0 && !bare;
  xyz_uncracked = vec3(0.0);
  xyz_ground = vec3(0.0);
  bool saunderson = saunderson_k.x >= 0.0;
  vec3 xyz = vec3(0.0);
  for (int node = 0; node < node_count; ++node) {
    float R = bare ? bare_reflectance[node]
                   : component(texelFetch(tile_data, ivec3(texel, dry_first_layer + node / 4), 0),
                               node % 4);
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
      xyz_uncracked += node_to_xyz[node] * (saunderson ? km_saunderson(R, saunderson_k.x, saunderson_k.y) : R) * body[node];
      xyz_ground += node_to_xyz[node] * (saunderson ? km_saunderson(ground, saunderson_k.x, saunderson_k.y) : ground);
    }
    R = crack_blend(crack, crack_wall, R);
    if (saunderson) R = km_saunderson(R, saunderson_k.x, saunderson_k.y);
    xyz += node_to_xyz[node] * R * body[node];
  }
  return xyz;
}

// Blinn-Phong's weights: the K-M colour as it is.
float[MAX_NODES] unit_body() {
  float body[MAX_NODES];
  for (int node = 0; node < MAX_NODES; ++node) body[node] = 1.0;
  return body;
}

vec3 cell_normal(ivec2 cell) {
  return shade_height_normal(total_height(cell - ivec2(1, 0)), total_height(cell + ivec2(1, 0)),
                             total_height(cell - ivec2(0, 1)), total_height(cell + ivec2(0, 1)),
                             cell_mm);
}

// The share of a uniform sky the paint's surface reflects: k1 with the surface on
// (saunderson_k.x < 0: off), as the CPU's TileRenderer passes shade::blinn_phong.
float sky_reflectance() { return max(saunderson_k.x, 0.0); }

// Colour, normal, wetness and relief light to a shaded colour (display XYZ, no sparkles).
vec3 shade_surface(vec3 xyz, vec3 normal, float volume, vec2 visibility) {
  vec2 material = shade_blend(dry_material, wet_material, volume * inverse_gloss_mm);
  vec2 shading = shade_blinn_phong(normal, to_light, ambient, material, visibility,
                                   sky_reflectance());
  return light_intensity * (xyz * shading.x + white_xyz * shading.y);
}

// A cell's K-M colour (weighted by the ghs body light) to its shaded colour: Blinn-Phong, or
// with the ghs model the surface's own light added.
vec3 shade_cell(vec3 xyz, vec3 surface_xyz, vec3 normal, float volume, vec2 visibility) {
  return ghs_enabled ? light_intensity * (xyz + surface_xyz)
                     : shade_surface(xyz, normal, volume, visibility);
}

// One cell as the CPU reference renders it, sparkles included; at close-up zoom over a
// crack (allow_close_up), the crack's inside at cell_position.
vec3 cell_colour(ivec2 cell, vec2 cell_position, bool allow_close_up) {
  float volume = texelFetch(surface, cell, 0).r;
  vec4 crack = crack_at(cell);
  // Zoomed in over a crack: the close-up needs the cell as if uncracked and the bare ground.
  bool close_up = allow_close_up && crack.x > 0.0 && close_up_zoomed(screen_to_cell);
  vec3 normal = cell_normal(cell);
  vec2 visibility = relief_visibility(surface, canvas_cells, cell, cell_mm);
  vec3 sparkles = light_intensity * flake_sparkles(cell, normal, total_height(cell));
  // The ghs surface: per node, the light the K-M body gets and the surface's own light.
  float body[MAX_NODES];
  vec3 surface_xyz = vec3(0.0);
  if (ghs_enabled) {
    float surface_light[MAX_NODES];
    ghs_shade(cell, node_count, normal, to_light, ambient, visibility, volume * inverse_gloss_mm,
              body, surface_light);
    for (int node = 0; node < node_count; ++node) surface_xyz += node_to_xyz[node] * surface_light[node];
  } else {
    body = unit_body();
  }
  vec3 xyz_uncracked;
  vec3 xyz_ground;
  vec3 xyz = cell_xyz(cell, volume, crack, close_up, body, xyz_uncracked, xyz_ground);
  vec3 shaded = shade_cell(xyz, surface_xyz, normal, volume, visibility) + sparkles;
  if (close_up) {
    // The crack's inside keeps the close-up's own shading.
    vec3 uncracked = shade_cell(xyz_uncracked, surface_xyz, normal, volume, visibility) + sparkles;
    vec4 inside = crack_close_up_colour(cell, canvas_cells, fract(cell_position), crack, cell_mm,
                                        uncracked, xyz_ground, to_light, ambient, dry_material,
                                        sky_reflectance(), white_xyz, light_intensity);
    shaded = inside.w > 0.0 ? inside.xyz : uncracked;
  }
  return subsurface_light(cell, shaded);
}

// Zoomed in: colour, wetness, normal and relief light of the four nearest cell centres
// blended bilinearly (the normal renormalised), then shaded; the sparkles of the pixel's cell.
vec3 interpolated_colour(vec2 cell_position, ivec2 cell) {
  vec2 p = cell_position - 0.5;
  ivec2 c0 = ivec2(floor(p));
  vec2 f = p - vec2(c0);
  vec3 xyz = vec3(0.0);
  float volume = 0.0;
  vec3 normal = vec3(0.0);
  vec2 visibility = vec2(0.0);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      ivec2 c = clamp(c0 + ivec2(i, j), ivec2(0), canvas_cells - 1);
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      float v = texelFetch(surface, c, 0).r;
      vec3 unused_uncracked;
      vec3 unused_ground;
      xyz += w * cell_xyz(c, v, crack_at(c), false, unit_body(), unused_uncracked, unused_ground);
      volume += w * v;
      normal += w * cell_normal(c);
      visibility += w * relief_visibility(surface, canvas_cells, c, cell_mm);
    }
  }
  vec3 sparkles = light_intensity * flake_sparkles(cell, cell_normal(cell), total_height(cell));
  return shade_surface(xyz, shade_normalized(normal), volume, visibility) + sparkles;
}

// The cells a zoomed-out pixel covers along one axis: its footprint [a, a + span) in cells
// meets cells first .. first + count - 1; weight(i) is how much of the footprint cell i holds.
struct Coverage {
  float a;
  float span;
  int first;
  int count;
};

Coverage coverage(float centre, float span) {
  float a = centre - 0.5 * span;
  int first = int(floor(a));
  return Coverage(a, span, first, int(ceil(a + span)) - first);
}

float coverage_weight(Coverage axis, int i) {
  float cell = float(axis.first + i);
  return (min(axis.a + axis.span, cell + 1.0) - max(axis.a, cell)) / axis.span;
}

// Zoomed out: the shaded colours of the cells under the pixel's footprint averaged in
// linear XYZ, each weighted by the share of the footprint it holds — a box filter, so fine
// relief (the weave, furrows) shows as its average, not as moiré beating against the
// pixels. The footprint is the pixel's axis-aligned extent in cells (a turned view's a
// little wider). Beyond 16 cells (over about 3 cells a pixel) n x n cells spread over the
// footprint stand for them, n about the cells a pixel each way, at most 4. With bilinear
// (the ghs model zoomed in: it shades per node, after the colour, so it cannot blend colour
// and normal first), the shaded colours of the four nearest cell centres, blended
// bilinearly.
vec3 footprint_colour(vec2 cell_position, float cells_per_pixel, bool allow_close_up,
                      bool bilinear, out bool any_inside) {
  mat2 to_cells = mat2(screen_to_cell[0].xy, screen_to_cell[1].xy);
  vec2 extent = abs(to_cells[0]) + abs(to_cells[1]);  // the footprint's size in cells
  Coverage along_x = coverage(cell_position.x, max(extent.x, 1e-4));
  Coverage along_y = coverage(cell_position.y, max(extent.y, 1e-4));
  bool exact = !bilinear && cells_per_pixel > 1.0 && along_x.count * along_y.count <= 16;
  int n = bilinear ? 2 : int(clamp(floor(cells_per_pixel + 0.5), 1.0, 4.0));
  ivec2 counts = exact ? ivec2(along_x.count, along_y.count) : ivec2(n);
  vec2 corner = cell_position - 0.5;
  ivec2 c0 = ivec2(floor(corner));
  vec2 f = corner - vec2(c0);
  vec3 sum = vec3(0.0);
  float weight_inside = 0.0;
  for (int j = 0; j < counts.y; ++j) {
    for (int i = 0; i < counts.x; ++i) {
      ivec2 c;
      vec2 at;
      float weight = 1.0;
      if (bilinear) {
        c = clamp(c0 + ivec2(i, j), ivec2(0), canvas_cells - 1);
        at = vec2(c) + 0.5;
        weight = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      } else if (exact) {
        c = ivec2(along_x.first + i, along_y.first + j);
        at = vec2(c) + 0.5;
        weight = coverage_weight(along_x, i) * coverage_weight(along_y, j);
      } else {
        vec2 offset = (vec2(i, j) + 0.5) / float(n) - 0.5;  // within the pixel
        at = cell_position + to_cells * offset;
        c = ivec2(floor(at));
      }
      if (!bilinear && (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, canvas_cells)))) {
        continue;
      }
      // One call of cell_colour in the whole shader: the compiled shader holds one copy.
      sum += weight * cell_colour(c, at, allow_close_up);
      weight_inside += weight;
    }
  }
  any_inside = weight_inside > 0.0;
  return any_inside ? sum / weight_inside : vec3(0.0);
}

void main() {
  vec2 cell_position = (screen_to_cell * vec3(gl_FragCoord.xy, 1.0)).xy;
  ivec2 cell = ivec2(floor(cell_position));
  bool outside = any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, canvas_cells));
  float cells_per_pixel = length(screen_to_cell[0].xy);
  bool zoomed_out = smooth_zoom && cells_per_pixel > 1.0 + 1e-4;
  bool zoomed_in = smooth_zoom && cells_per_pixel < 1.0 - 1e-4;
  if (!zoomed_out && outside) {
    frag_color = vec4(background, 1.0);
    return;
  }
  bool close_up = !outside && crack_at(cell).x > 0.0 && close_up_zoomed(screen_to_cell);
  vec3 shaded;
  if (zoomed_in && !ghs_enabled && !close_up) {
    shaded = interpolated_colour(cell_position, cell);
  } else {
    // Zoomed out, the cells under the pixel's footprint; zoomed in with ghs, the four nearest
    // cells; else the pixel's own cell (a footprint of one, exactly at cell_position), with a
    // crack's close-up.
    bool bilinear = zoomed_in && !close_up;
    bool any_inside;
    shaded = footprint_colour(cell_position, zoomed_out ? cells_per_pixel : 1.0,
                              !zoomed_out && !bilinear, bilinear, any_inside);
    if (!any_inside) {
      frag_color = vec4(background, 1.0);
      return;
    }
  }
  frag_color = canvas_output(shaded);
}
