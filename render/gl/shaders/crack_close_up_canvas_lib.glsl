// The window's close-up of cracks: zoomed in past close_up_min_pixels pixels per cell, a
// pixel over a crack's opening shows the point of the cavity its view ray reaches
// (close_up_pixel), as the CPU's render_painting_close_up does (render/src/
// crack_close_up_painting.cpp): the cell's colour without the crack and the colour of what
// its walls expose, mixed in linear sRGB. Needs shading_lib, cracks_lib and
// crack_close_up_lib.

uniform bool close_up_on;                 // cracks on and a crack texture exists
uniform float close_up_min_pixels;        // the close-up shows from this many pixels per cell
uniform sampler2D crack_shapes;           // per cell: depth L, half-width R (mm), ground normal x, y
uniform mat3 xyz_to_linear_rgb;           // the display's XYZ (D65) to linear sRGB
uniform mat3 linear_rgb_to_xyz;
uniform vec3 close_up_suns[CLOSE_UP_MAX_RAYS];          // over the light's disc, canvas frame
uniform vec3 close_up_suns_swapped[CLOSE_UP_MAX_RAYS];  // x and y swapped (grooves along x)
uniform int close_up_rays;
uniform float close_up_e_sky;             // irradiances as shares of the canvas's
uniform float close_up_e_sun;

// Whether the view magnifies cells enough for the close-up (rotation keeps the scale).
bool close_up_zoomed(mat3 screen_to_cell) {
  float cells_per_pixel = length(screen_to_cell[0].xy);
  return close_up_on && cells_per_pixel * close_up_min_pixels <= 1.0;
}

bool close_up_cracked(ivec2 cell, ivec2 cells) {
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, cells))) return false;
  return texelFetch(crack_cells, cell, 0).x > 0.0;
}

// A groove runs the way its cracked neighbours run the longest (within two cells; x on a
// tie), as the CPU decides it.
bool close_up_along_x(ivec2 cell, ivec2 cells) {
  int run_x = 0, run_y = 0;
  for (int k = -2; k <= 2; ++k) {
    run_x += close_up_cracked(cell + ivec2(k, 0), cells) ? 1 : 0;
    run_y += close_up_cracked(cell + ivec2(0, k), cells) ? 1 : 0;
  }
  return run_x >= run_y;
}

// The close-up colour (display XYZ) of the pixel at `in_cell` (0..1 across the cell) of a
// cracked cell, or w = -1 where the pixel is outside the crack's opening. surface_xyz: the
// cell shaded as if uncracked; ground_reflectance_xyz: the ground's colour before shading.
vec4 crack_close_up_colour(ivec2 cell, ivec2 cells, vec2 in_cell, vec4 crack, float cell_mm,
                           vec3 surface_xyz, vec3 ground_reflectance_xyz, vec3 to_light,
                           float ambient, vec2 dry_material, float sky_reflectance,
                           vec3 white_xyz, float light_intensity) {
  vec4 dims = texelFetch(crack_shapes, cell, 0);
  float code = abs(crack.w) - 1.0;
  int shape = int(floor(code / crack_table_stride));
  bool swap_xy = shape <= 2 && close_up_along_x(cell, cells);
  vec2 at = (in_cell - 0.5) * cell_mm;  // canvas frame, from the cell's centre
  vec3 o = swap_xy ? vec3(at.y, at.x, 0.0) : vec3(at, 0.0);
  if (close_up_radial(shape, o) >= dims.y) return vec4(-1.0);

  vec3 walls_xyz = surface_xyz;
  if (crack.w > 0.0) {
    // A crack through the film shows the bare canvas, shaded as the CPU shades it.
    vec2 s = shade_blinn_phong(vec3(dims.z, dims.w, sqrt(max(0.0, 1.0 - dot(dims.zw, dims.zw)))),
                               to_light, ambient, dry_material, vec2(1.0), sky_reflectance);
    walls_xyz = light_intensity * (ground_reflectance_xyz * s.x + white_xyz * s.y);
  }
  vec3 walls = xyz_to_linear_rgb * walls_xyz;
  vec4 rgb;
  if (swap_xy) {
    rgb = close_up_pixel(shape, dims.x, dims.y, o, vec3(0.0, 0.0, 1.0), close_up_suns_swapped,
                         close_up_rays, close_up_e_sky, close_up_e_sun, crack.z, vec4(walls, 0.0));
  } else {
    rgb = close_up_pixel(shape, dims.x, dims.y, o, vec3(0.0, 0.0, 1.0), close_up_suns,
                         close_up_rays, close_up_e_sky, close_up_e_sun, crack.z, vec4(walls, 0.0));
  }
  return vec4(linear_rgb_to_xyz * rgb.rgb, 1.0);
}
