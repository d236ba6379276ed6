// Cracks seen from afar: Gouffe's apparent reflectance of the cavity blended into the cell by
// the crack's area, as the CPU reference does it (render/cracks/src/crack_shading.cpp and
// gouffe.hpp, cracks::apparent_reflectance). Needs MAX_NODES.

uniform bool crack_on;                    // false: no crack anywhere, no texture read
uniform sampler2D crack_cells;            // per cell: coverage, F, G, walls are the ground (1/0)
uniform float crack_ground[MAX_NODES];    // the ground's reflectance per node

// The cell's crack optics (coverage 0 where it has none).
vec4 crack_at(ivec2 cell) {
  return crack_on ? texelFetch(crack_cells, cell, 0) : vec4(0.0);
}

// The reflectance of the crack's walls at a node: the ground, or the cell's dry stack.
float crack_walls(vec4 crack, int node, float dry_stack) {
  return crack.w > 0.5 ? crack_ground[node] : dry_stack;
}

// rho = rho0 F + rho0^2 (1 - F) G / (1 - rho0 (1 - G)), blended by the coverage.
float crack_blend(vec4 crack, float walls, float surface) {
  if (crack.x <= 0.0) return surface;
  float rho0 = clamp(walls, 0.0, 1.0);
  float F = crack.y, G = crack.z;
  float denom = 1.0 - rho0 * (1.0 - G);
  float rho = rho0 * F + (denom > 0.0 ? rho0 * rho0 * (1.0 - F) * G / denom : 0.0);
  return (1.0 - crack.x) * surface + crack.x * rho;
}
