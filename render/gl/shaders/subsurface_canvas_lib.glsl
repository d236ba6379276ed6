// The subsurface spread in the canvas pass (docs/surface.md, "The spread on the GPU"): each
// cell's shaded light gains the spread's change, which subsurface_spread_frag computed from
// the body's light alone; the map's debug view; the body pass's linear output.
// Assembled after the display function `vec4 ocio_display(vec4 xyz)` and the C++'s define of
// SPREAD_MAP_FULL_SCALE (render::kSubsurfaceMapFullScaleCells).

uniform bool spread_enabled;       // the ghs surface with its subsurface spread
uniform sampler2D spread_delta;    // per cell (texel row = cell row): linear-sRGB change
uniform sampler2D spread_lengths;  // per cell: each channel's spread length in cells, 0: none
uniform bool spread_map_view;      // show the map in place of the painting
uniform mat3 spread_srgb_to_xyz;   // linear sRGB to the pass's display-referred XYZ
uniform mat3 spread_xyz_to_srgb;   // and back
uniform bool linear_srgb_output;   // the body pass: linear sRGB, no display transform

// A cell's shaded light (XYZ) with the spread, or the map's colour.
vec3 subsurface_light(ivec2 cell, vec3 shaded) {
  vec3 light = spread_enabled ? shaded + spread_srgb_to_xyz * texelFetch(spread_delta, cell, 0).rgb
                              : shaded;
  if (spread_map_view) {
    vec3 lengths = texelFetch(spread_lengths, cell, 0).rgb;
    if (any(greaterThan(lengths, vec3(0.0)))) {
      return spread_srgb_to_xyz * min(lengths / SPREAD_MAP_FULL_SCALE, vec3(1.0));
    }
    return 0.25 * light;  // the painting dimmed beneath the map
  }
  return light;
}

vec4 canvas_output(vec3 xyz) {
  if (linear_srgb_output) return vec4(spread_xyz_to_srgb * xyz, 1.0);
  return vec4(ocio_display(vec4(xyz, 1.0)).rgb, 1.0);
}
