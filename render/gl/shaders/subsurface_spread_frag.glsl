// The subsurface spread as a gather (docs/surface.md): the change the spread makes at each
// cell, spread(body) − body, where render::apply_spread scatters each mapped cell's light
// by its kernel. A cell gathers from every mapped cell within `radius`, each channel by its
// own kernel; light the CPU keeps in an edge cell (its offsets clamped to the canvas) is
// gathered there as the kernel's sum over those offsets, from its prefix sums.
// Each cell looks only as far as its block's radius: the largest kernel radius among the
// mapped cells of its block and the eight around it (blocks as wide as the largest radius).
// Assembled after #version and the C++'s defines of SPREAD_MAX_RADIUS
// (render::kSubsurfaceMaxRadius), SPREAD_ATLAS_COLUMNS and SPREAD_BLOCK (subsurface_spread.cpp).

#define SPREAD_SIDE (2 * SPREAD_MAX_RADIUS + 1)

uniform sampler2D body;        // the body's linear sRGB; GL rows bottom-up (row H-1-y: cell y)
uniform sampler2D kernel_ids;  // per cell (texel row = cell row): kernel + 1 per channel, 0: none
uniform sampler2D kernels;     // SIDE x SIDE blocks: r weight, g prefix sum over the block
uniform sampler2D block_radius;  // per SPREAD_BLOCK x SPREAD_BLOCK cells: how far to gather
uniform ivec2 canvas_cells;

out vec4 frag_color;

ivec2 kernel_origin(int id) {
  return ivec2(id % SPREAD_ATLAS_COLUMNS, id / SPREAD_ATLAS_COLUMNS) * SPREAD_SIDE;
}

// Sum of the weights over padded offsets [0, i] x [0, j].
float prefix(ivec2 origin, int i, int j) {
  if (i < 0 || j < 0) return 0.0;
  return texelFetch(kernels, origin + ivec2(i, j), 0).g;
}

// The weights over padded offsets [lo, hi] (one offset: its own weight).
float kernel_weight(int id, ivec2 lo, ivec2 hi) {
  ivec2 origin = kernel_origin(id);
  if (lo == hi) return texelFetch(kernels, origin + lo, 0).r;
  return prefix(origin, hi.x, hi.y) - prefix(origin, lo.x - 1, hi.y) -
         prefix(origin, hi.x, lo.y - 1) + prefix(origin, lo.x - 1, lo.y - 1);
}

vec3 body_at(ivec2 cell) {
  return texelFetch(body, ivec2(cell.x, canvas_cells.y - 1 - cell.y), 0).rgb;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 last = canvas_cells - 1;
  vec3 delta = vec3(0.0);
  int radius = int(texelFetch(block_radius, p / SPREAD_BLOCK, 0).r + 0.5);
  for (int sy = max(p.y - radius, 0); sy <= min(p.y + radius, last.y); ++sy) {
    for (int sx = max(p.x - radius, 0); sx <= min(p.x + radius, last.x); ++sx) {
      ivec2 s = ivec2(sx, sy);
      vec3 ids = texelFetch(kernel_ids, s, 0).rgb;
      if (ids == vec3(0.0)) continue;
      vec3 light = body_at(s);
      // The offsets from s whose clamped target is p.
      ivec2 lo = p - s + SPREAD_MAX_RADIUS;
      ivec2 hi = lo;
      if (p.x == 0) lo.x = 0;
      if (p.x == last.x) hi.x = SPREAD_SIDE - 1;
      if (p.y == 0) lo.y = 0;
      if (p.y == last.y) hi.y = SPREAD_SIDE - 1;
      for (int c = 0; c < 3; ++c) {
        if (ids[c] > 0.5) delta[c] += light[c] * kernel_weight(int(ids[c]) - 1, lo, hi);
      }
    }
  }
  vec3 own = texelFetch(kernel_ids, p, 0).rgb;
  vec3 own_light = body_at(p);
  for (int c = 0; c < 3; ++c) {
    if (own[c] > 0.5) delta[c] -= own_light[c];
  }
  frag_color = vec4(delta, 1.0);
}
