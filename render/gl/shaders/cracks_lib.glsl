// Cracks seen from afar: the cavity's apparent reflectance blended into the cell by the
// crack's area, as the CPU reference does it (optics/cracks/src/cavity_look.cpp): Gouffe's
// closed form (gouffe.hpp, cracks::apparent_reflectance) plus, in the corrected model, the
// measured correction blended for the light (cavity_correction.cpp, interpolate_difference in
// cavity_table.cpp). Needs
// MAX_NODES.

uniform bool crack_on;                    // false: no crack anywhere, no texture read
uniform sampler2D crack_cells;            // per cell: coverage, F, G, packed shape and L/R
uniform float crack_ground[MAX_NODES];    // the ground's reflectance per node

uniform bool crack_corrected;             // the measured correction on (RenderSettings::crack_model)
uniform sampler2D crack_table;            // rho_table - rho_Gouffe for the light: x rho0, y shape, L/R
uniform int crack_table_rows;             // L/R rows per shape
uniform int crack_table_rho0s;            // rho0 nodes (0 .. 1)
uniform float crack_table_stride;         // packing of the cells' fourth channel
uniform float crack_table_last_F[CRACK_SHAPES];  // F and G of each shape at the deepest row
uniform float crack_table_last_G[CRACK_SHAPES];  // (CRACK_SHAPES #defined by cracks_glsl())

// The cell's crack optics (coverage 0 where it has none).
vec4 crack_at(ivec2 cell) {
  return crack_on ? texelFetch(crack_cells, cell, 0) : vec4(0.0);
}

// The reflectance of the crack's walls at a node: the ground (fourth channel positive), or
// the cell's dry stack.
float crack_walls(vec4 crack, int node, float dry_stack) {
  return crack.w > 0.0 ? crack_ground[node] : dry_stack;
}

// rho = rho0 F + rho0^2 (1 - F) G / (1 - rho0 (1 - G)).
float crack_gouffe(float rho0, float F, float G) {
  float denom = 1.0 - rho0 * (1.0 - G);
  return rho0 * F + (denom > 0.0 ? rho0 * rho0 * (1.0 - F) * G / denom : 0.0);
}

// The table's difference, bilinear in (u, rho0) with u clamped to its rows.
float crack_table_difference(int shape, float u, float rho0) {
  int last = crack_table_rows - 1;
  float uc = clamp(u, 0.0, float(last));
  float v = rho0 * float(crack_table_rho0s - 1);
  int i0 = min(int(uc), last - 1);
  int j0 = min(int(v), crack_table_rho0s - 2);
  float fu = uc - float(i0), fv = v - float(j0);
  int row = shape * crack_table_rows + i0;
  float d00 = texelFetch(crack_table, ivec2(j0, row), 0).r;
  float d01 = texelFetch(crack_table, ivec2(j0 + 1, row), 0).r;
  float d10 = texelFetch(crack_table, ivec2(j0, row + 1), 0).r;
  float d11 = texelFetch(crack_table, ivec2(j0 + 1, row + 1), 0).r;
  return (1.0 - fu) * ((1.0 - fv) * d00 + fv * d01) + fu * ((1.0 - fv) * d10 + fv * d11);
}

// The cavity's apparent reflectance, blended by the coverage.
float crack_blend(vec4 crack, float walls, float surface) {
  if (crack.x <= 0.0) return surface;
  float rho0 = clamp(walls, 0.0, 1.0);
  float gouffe = crack_gouffe(rho0, crack.y, crack.z);
  float rho = gouffe;
  if (crack_corrected) {
    // Unpack |w| = 1 + shape stride + (u + 1).
    float code = abs(crack.w) - 1.0;
    int shape = int(floor(code / crack_table_stride));
    float u = code - float(shape) * crack_table_stride - 1.0;
    float d = crack_table_difference(shape, u, rho0);
    if (u < 0.0) {
      d *= u + 1.0;  // fades out towards L = 0
    } else if (u > float(crack_table_rows - 1)) {
      float last = crack_gouffe(rho0, crack_table_last_F[shape], crack_table_last_G[shape]);
      d *= last > 0.0 ? min(1.0, gouffe / last) : 0.0;
    }
    rho = clamp(gouffe + d, 0.0, rho0);
  }
  return (1.0 - crack.x) * surface + crack.x * rho;
}
