#include "impasto/render/crack_close_up.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/cracks/cavity.hpp"
#include "impasto/cracks/close_up.hpp"

namespace impasto::render {
namespace {

using cracks::CavityShape;
using cracks::Vec3d;

// The cavity's frame has grooves across x and along y (cracks/close_up.hpp). A groove along
// the canvas's x swaps the two axes; the swap keeps lengths and angles, all the shading uses.
Vec3d to_cavity(const CanvasVec& v, bool swap_xy) {
  return swap_xy ? Vec3d{v.y, v.x, v.z} : Vec3d{v.x, v.y, v.z};
}

// The cavity's profile: the air inside it is a convex set, bounded by the opening (z = 0,
// distance from the axis below R) and the walls.
struct Profile {
  CavityShape shape;
  double L, R;

  double radial(const Vec3d& p) const {
    return cracks::is_groove(shape) ? std::abs(p.x) : std::hypot(p.x, p.y);
  }
  // Height of the wall below the point at distance rho < R from the axis.
  double floor_z(double rho) const {
    switch (shape) {
      case CavityShape::ArcGroove:
      case CavityShape::SpherePit: {
        const double r = (R * R + L * L) / (2.0 * L);  // radius of the arc / sphere
        return (r - L) - std::sqrt(std::max(0.0, r * r - rho * rho));
      }
      case CavityShape::VGroove:
      case CavityShape::ConePit:
        return -L * (1.0 - rho / R);
      default:
        return -L;  // box, cylinder: flat bottom
    }
  }
  bool inside(const Vec3d& p) const {
    const double rho = radial(p);
    return p.z <= 0.0 && rho < R && p.z >= floor_z(rho);
  }
  // Unit radial direction of p in the cross-section (x for grooves).
  Vec3d outward(const Vec3d& p) const {
    const double rho = radial(p);
    if (rho <= 0.0) return {1.0, 0.0, 0.0};
    return cracks::is_groove(shape) ? Vec3d{p.x / rho, 0.0, 0.0} : Vec3d{p.x / rho, p.y / rho, 0.0};
  }
  // The wall point where a ray from the opening point `o` going `d` (down) leaves the air.
  // Convexity makes the exit unique: bisection between a point inside and one surely below.
  cracks::CavityWallPoint hit(const Vec3d& o, const Vec3d& d) const {
    double t_in = 0.0, t_out = (1.01 * L + 1e-9 * R) / -d.z;
    for (int i = 0; i < 60; ++i) {
      const double t = 0.5 * (t_in + t_out);
      (inside({o.x + t * d.x, o.y + t * d.y, o.z + t * d.z}) ? t_in : t_out) = t;
    }
    const Vec3d p{o.x + t_in * d.x, o.y + t_in * d.y, o.z + t_in * d.z};
    return {p, normal_at(p)};
  }
  // Unit normal into the air at a wall point.
  Vec3d normal_at(const Vec3d& p) const {
    const Vec3d e = outward(p);
    switch (shape) {
      case CavityShape::ArcGroove:
      case CavityShape::SpherePit: {
        const double r = (R * R + L * L) / (2.0 * L);
        const Vec3d c{0.0, cracks::is_groove(shape) ? p.y : 0.0, r - L};
        const Vec3d n{c.x - p.x, c.y - p.y, c.z - p.z};
        const double len = std::sqrt(dot(n, n));
        return {n.x / len, n.y / len, n.z / len};
      }
      case CavityShape::VGroove:
      case CavityShape::ConePit: {
        const double h = std::hypot(R, L);
        return {-e.x * L / h, -e.y * L / h, R / h};
      }
      default:  // the nearer of the vertical wall and the flat bottom
        if (R - radial(p) < p.z + L) return {-e.x, -e.y, 0.0};
        return {0.0, 0.0, 1.0};
    }
  }
  // Whether a ray from wall point p toward s leaves through the opening: the air is convex,
  // so it does exactly when it crosses z = 0 inside the rim.
  bool sees(const cracks::CavityWallPoint& p, const Vec3d& s) const {
    if (s.z <= 0.0 || dot(p.normal, s) <= 0.0) return false;
    const double t = -p.position.z / s.z;
    return radial({p.position.x + t * s.x, p.position.y + t * s.y, 0.0}) < R;
  }
};

void check_unit(const CanvasVec& v, const char* field) {
  const double len2 = v.x * v.x + v.y * v.y + v.z * v.z;
  if (!std::isfinite(len2) || std::abs(len2 - 1.0) > 1e-6) {
    throw std::invalid_argument(std::string(field) + ": expected a unit vector");
  }
}

}  // namespace

std::vector<CanvasVec> close_up_light_directions(const CloseUpLight& light) {
  const Vec3d c = light.toward_light;
  // Two unit vectors across c.
  const Vec3d a = std::abs(c.z) < 0.9 ? Vec3d{0.0, 0.0, 1.0} : Vec3d{1.0, 0.0, 0.0};
  const Vec3d across = cross(a, c);
  const double ul = length(across);
  const Vec3d u{across.x / ul, across.y / ul, across.z / ul};
  const Vec3d v = cross(c, u);
  const int n = light.shadow_rays;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<CanvasVec> out(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double radius = light.angular_radius_rad * std::sqrt((k + 0.5) / n);
    const double phi = golden * k;
    const double x = std::tan(radius) * std::cos(phi), y = std::tan(radius) * std::sin(phi);
    Vec3d s{c.x + x * u.x + y * v.x, c.y + x * u.y + y * v.y, c.z + x * u.z + y * v.z};
    const double len = std::sqrt(dot(s, s));
    out[static_cast<std::size_t>(k)] = {s.x / len, s.y / len, s.z / len};
  }
  return out;
}

void validate(const CloseUpLight& light, const CloseUpView& view) {
  check_unit(light.toward_light, "light.toward_light");
  check_unit(view.toward_eye, "view.toward_eye");
  if (!(view.toward_eye.z > 0.0)) {
    throw std::invalid_argument("view.toward_eye: must look at the canvas from above (z > 0)");
  }
  if (!(light.sky_fraction >= 0.0 && light.sky_fraction <= 1.0)) {
    throw std::invalid_argument("light.sky_fraction: expected 0..1");
  }
  if (!(light.angular_radius_rad >= 0.0 && light.angular_radius_rad < 1.0)) {
    throw std::invalid_argument("light.angular_radius_rad: expected 0..1 rad");
  }
  if (light.shadow_rays < 1) throw std::invalid_argument("light.shadow_rays: expected >= 1");
  if (light.toward_light.z <= 0.0 && light.sky_fraction <= 0.0) {
    throw std::invalid_argument("light: the canvas gets no light (below the horizon, no sky)");
  }
}

void crack_close_up_cell(const paintcore::CrackRecord& record, double cell_mm, bool groove_along_x,
                         int pixels_per_cell, std::span<const float> surface,
                         std::span<const float> wall, const CloseUpLight& light,
                         const CloseUpView& view, std::span<float> out) {
  const std::size_t channels = surface.size();
  const int P = pixels_per_cell;
  if (P < 1 || wall.size() != channels ||
      out.size() != static_cast<std::size_t>(P) * static_cast<std::size_t>(P) * channels) {
    throw std::invalid_argument("crack_close_up_cell: sizes of surface, wall and out disagree");
  }
  validate(light, view);
  for (std::size_t i = 0; i < out.size(); i += channels) {
    std::copy(surface.begin(), surface.end(), out.begin() + static_cast<std::ptrdiff_t>(i));
  }
  if (!record.has_crack()) return;

  const auto shape = static_cast<CavityShape>(record.shape);
  const cracks::CavityDims dims{record.depth_mm, record.half_width_mm};
  const Profile profile{shape, dims.depth_mm, dims.half_width_mm};
  const bool swap_xy = cracks::is_groove(shape) && groove_along_x;
  const Vec3d eye = to_cavity(view.toward_eye, swap_xy);
  const Vec3d down{-eye.x, -eye.y, -eye.z};
  std::vector<Vec3d> suns;
  for (const CanvasVec& s : close_up_light_directions(light)) suns.push_back(to_cavity(s, swap_xy));

  const CloseUpIrradiance irradiance = close_up_irradiance(light);
  const double e_sky = irradiance.sky, e_sun = irradiance.sun;
  // Gouffe's uniform walls: the mean first irradiance of the walls is (A/S) E_canvas = G,
  // each bounce returning rho0 (1 - G) of it.
  const double G = cracks::view_factors(shape, dims).G;

  const double pixel_mm = cell_mm / P;
  for (int py = 0; py < P; ++py) {
    for (int px = 0; px < P; ++px) {
      // Pixel centre relative to the cell's centre, canvas frame.
      const CanvasVec at{(px + 0.5) * pixel_mm - 0.5 * cell_mm,
                         (py + 0.5) * pixel_mm - 0.5 * cell_mm, 0.0};
      const Vec3d o = to_cavity(at, swap_xy);
      if (profile.radial(o) >= profile.R) continue;  // outside the opening
      const cracks::CavityWallPoint p = profile.hit(o, down);
      const double f_point = cracks::opening_view_factor(shape, dims, p);
      double lit = 0.0;  // mean of cos(normal, light) over the disc's unshadowed rays
      for (const Vec3d& s : suns) {
        if (profile.sees(p, s)) lit += dot(p.normal, s);
      }
      const double direct = e_sun * lit / static_cast<double>(suns.size());
      float* pixel = out.data() + (static_cast<std::size_t>(py) * P + px) * channels;
      for (std::size_t c = 0; c < channels; ++c) {
        const double rho0 = wall[c];
        const double walls = rho0 * G / (1.0 - rho0 * (1.0 - G));
        // Radiosity over the canvas's irradiance: the pixel's reflectance (its radiance
        // B / pi over a white canvas's 1 / pi; the ray's footprint on the wall carries the
        // cos(view, normal) of I = pi I_gray cos).
        pixel[c] = static_cast<float>(rho0 * (e_sky * f_point + direct + (1.0 - f_point) * walls));
      }
    }
  }
}

CloseUpIrradiance close_up_irradiance(const CloseUpLight& light) {
  // E_sky + E_sun cos(z) = 1 when the light is up; below the horizon only the sky lights.
  const double sun_z = light.toward_light.z;
  if (sun_z <= 0.0) return {1.0, 0.0};
  return {light.sky_fraction, (1.0 - light.sky_fraction) / sun_z};
}

void check_close_up_region(const CellRegion& region, int pixels_per_cell, int width_cells,
                           int height_cells) {
  if (region.w < 1 || region.h < 1 || region.x < 0 || region.y < 0 ||
      region.x + region.w > width_cells || region.y + region.h > height_cells) {
    throw std::runtime_error("close-up: field 'region' " + std::to_string(region.x) + "," +
                             std::to_string(region.y) + "," + std::to_string(region.w) + "," +
                             std::to_string(region.h) + " is not inside the canvas " +
                             std::to_string(width_cells) + "x" + std::to_string(height_cells));
  }
  if (pixels_per_cell < 1 || pixels_per_cell > 256) {
    throw std::runtime_error("close-up: field 'zoom' must be 1..256 pixels per cell");
  }
}

Image render_crack_close_up(const paintcore::Canvas& canvas, const Image& surface,
                            const Image& walls, const CellRegion& region, int pixels_per_cell,
                            const CloseUpLight& light, const CloseUpView& view) {
  const int W = canvas.width_cells(), H = canvas.height_cells();
  if (surface.width != W || surface.height != H || walls.width != W || walls.height != H) {
    throw std::runtime_error("close-up: surface and walls images must be the canvas's size");
  }
  check_close_up_region(region, pixels_per_cell, W, H);
  const int P = pixels_per_cell;
  auto record_at = [&](int x, int y) -> paintcore::CrackRecord {
    if (x < 0 || y < 0 || x >= W || y >= H) return {};
    const int tile = (y / paintcore::kTileSize) * canvas.tiles_x() + x / paintcore::kTileSize;
    const paintcore::CrackTile* t = canvas.cracks().tile(tile);
    if (t == nullptr) return {};
    return t->cells[static_cast<std::size_t>((y % paintcore::kTileSize) * paintcore::kTileSize +
                                             x % paintcore::kTileSize)];
  };
  Image image{region.w * P, region.h * P, {}};
  image.rgb.resize(3 * static_cast<std::size_t>(image.width) * image.height);
  std::vector<float> cell(3 * static_cast<std::size_t>(P) * P);
  for (int cy = region.y; cy < region.y + region.h; ++cy) {
    for (int cx = region.x; cx < region.x + region.w; ++cx) {
      const paintcore::CrackRecord record = record_at(cx, cy);
      // A groove runs the way its cracked neighbours run the longest (a crack drawn across
      // several cells of width still runs along its length).
      auto run = [&](int dx, int dy) {
        int n = 0;
        for (int k = -2; k <= 2; ++k) n += record_at(cx + k * dx, cy + k * dy).has_crack() ? 1 : 0;
        return n;
      };
      const bool along_x = run(1, 0) >= run(0, 1);
      crack_close_up_cell(record, canvas.cell_mm(), along_x, P, {surface.pixel(cx, cy), 3},
                          {walls.pixel(cx, cy), 3}, light, view, cell);
      for (int py = 0; py < P; ++py) {
        std::copy_n(cell.data() + 3 * static_cast<std::size_t>(py) * P, 3 * P,
                    image.pixel((cx - region.x) * P, (cy - region.y) * P + py));
      }
    }
  }
  return image;
}

}  // namespace impasto::render
