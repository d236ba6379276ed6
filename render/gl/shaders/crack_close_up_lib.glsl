// The close-up of one cracked cell, per pixel: the GLSL port of render/src/crack_close_up.cpp
// (docs/cracks.md, "Close-up rendering"). The cavity's frame: opening at z = 0, grooves
// across x and along y, pits about the z axis; lengths in mm. Shape codes are the cracks
// library's: 0 arc groove, 1 V groove, 2 box groove, 3 sphere pit, 4 cone pit, 5 cylinder pit.

const float CLOSE_UP_PI = 3.14159265358979;

bool close_up_is_groove(int shape) { return shape <= 2; }

float close_up_radial(int shape, vec3 p) {
  return close_up_is_groove(shape) ? abs(p.x) : length(p.xy);
}

// Height of the wall below the point at distance rho < R from the axis.
float close_up_floor_z(int shape, float L, float R, float rho) {
  if (shape == 0 || shape == 3) {
    float r = (R * R + L * L) / (2.0 * L);
    return (r - L) - sqrt(max(0.0, r * r - rho * rho));
  }
  if (shape == 1 || shape == 4) return -L * (1.0 - rho / R);
  return -L;
}

bool close_up_inside(int shape, float L, float R, vec3 p) {
  float rho = close_up_radial(shape, p);
  return p.z <= 0.0 && rho < R && p.z >= close_up_floor_z(shape, L, R, rho);
}

vec3 close_up_outward(int shape, vec3 p) {
  float rho = close_up_radial(shape, p);
  if (rho <= 0.0) return vec3(1.0, 0.0, 0.0);
  return close_up_is_groove(shape) ? vec3(p.x / rho, 0.0, 0.0) : vec3(p.xy / rho, 0.0);
}

// Unit normal into the air at a wall point.
vec3 close_up_normal(int shape, float L, float R, vec3 p) {
  vec3 e = close_up_outward(shape, p);
  if (shape == 0 || shape == 3) {
    float r = (R * R + L * L) / (2.0 * L);
    vec3 c = vec3(0.0, close_up_is_groove(shape) ? p.y : 0.0, r - L);
    return normalize(c - p);
  }
  if (shape == 1 || shape == 4) {
    float h = sqrt(R * R + L * L);
    return vec3(-e.xy * L / h, R / h);
  }
  if (R - close_up_radial(shape, p) < p.z + L) return vec3(-e.xy, 0.0);
  return vec3(0.0, 0.0, 1.0);
}

// Where the view ray from opening point o going d (down) leaves the convex air: bisection.
vec3 close_up_hit(int shape, float L, float R, vec3 o, vec3 d) {
  float t_in = 0.0;
  float t_out = (1.01 * L + 1e-9 * R) / -d.z;
  for (int i = 0; i < 40; ++i) {
    float t = 0.5 * (t_in + t_out);
    if (close_up_inside(shape, L, R, o + t * d)) t_in = t; else t_out = t;
  }
  return o + t_in * d;
}

// A wall point's view factor to the opening (cracks::opening_view_factor).
float close_up_view_factor(int shape, float L, float R, vec3 p, vec3 n) {
  if (close_up_is_groove(shape)) {
    float s[2];
    for (int k = 0; k < 2; ++k) {
      float rim = k == 0 ? R : -R;
      vec2 dv = vec2(rim - p.x, -p.z);
      float len = length(dv);
      s[k] = len == 0.0 ? 0.0 : (n.z * dv.x - n.x * dv.y) / len;
    }
    return clamp(0.5 * abs(s[0] - s[1]), 0.0, 1.0);
  }
  if (shape == 3) return R * R / (R * R + L * L);
  if (shape == 5) {
    float depth = -p.z;
    float rho = length(p.xy);
    if (n.z > 0.5) {
      float h2 = depth * depth, a2 = R * R, r2 = rho * rho;
      return 0.5 * (1.0 - (h2 + r2 - a2) / sqrt((h2 + r2 + a2) * (h2 + r2 + a2) - 4.0 * a2 * r2));
    }
    float X = depth / (2.0 * R);
    return (X * X + 0.5) / sqrt(X * X + 1.0) - X;
  }
  // The contour integral over the rim, trapezoid rule (512 nodes as on the CPU).
  float sum = 0.0;
  for (int i = 0; i < 512; ++i) {
    float phi = 2.0 * CLOSE_UP_PI * (float(i) + 0.5) / 512.0;
    vec3 r = vec3(R * cos(phi), R * sin(phi), 0.0) - p;
    vec3 dr = vec3(-R * sin(phi), R * cos(phi), 0.0);
    float r2 = dot(r, r);
    if (r2 > 0.0) sum += dot(n, cross(r, dr)) / r2;
  }
  return clamp(abs(sum / 512.0), 0.0, 1.0);
}

// Whether a ray from wall point p (normal n) toward s leaves through the opening.
bool close_up_sees(int shape, float R, vec3 p, vec3 n, vec3 s) {
  if (s.z <= 0.0 || dot(n, s) <= 0.0) return false;
  float t = -p.z / s.z;
  return close_up_radial(shape, vec3(p.xy + t * s.xy, 0.0)) < R;
}

// The reflectance of the pixel at cavity-frame opening point o (z = 0), or -1 outside the
// opening. eye: unit, toward the viewer; suns[0..rays): unit directions over the light's
// disc; e_sky, e_sun: irradiances as shares of the canvas's; G: Gouffe's G; rho0: the walls.
const int CLOSE_UP_MAX_RAYS = 64;
vec4 close_up_pixel(int shape, float L, float R, vec3 o, vec3 eye, vec3 suns[CLOSE_UP_MAX_RAYS],
                    int rays, float e_sky, float e_sun, float G, vec4 rho0) {
  if (close_up_radial(shape, o) >= R) return vec4(-1.0);
  vec3 p = close_up_hit(shape, L, R, o, -eye);
  vec3 n = close_up_normal(shape, L, R, p);
  float f_point = close_up_view_factor(shape, L, R, p, n);
  float lit = 0.0;
  for (int k = 0; k < rays; ++k) {
    if (close_up_sees(shape, R, p, n, suns[k])) lit += dot(n, suns[k]);
  }
  float direct = e_sun * lit / float(rays);
  vec4 walls = rho0 * G / (1.0 - rho0 * (1.0 - G));
  return rho0 * (e_sky * f_point + direct + (1.0 - f_point) * walls);
}
