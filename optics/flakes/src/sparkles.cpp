#include "impasto/flakes/sparkles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/flakes/counter_rng.hpp"
#include "impasto/flakes/fresnel.hpp"
#include "impasto/flakes/sparkle_math.hpp"
#include "light_checks.hpp"

namespace impasto::flakes {

// What one cell under one light needs before any random number is drawn. The energy
// factors are only worked out for the few cells that do sparkle.
struct SparkleRenderer::Setup {
  double mean_count = 0;  // ⟨N⟩
  double cos_light = 1, cos_view = 1, cos_light_in = 1, cos_view_in = 1;
  double cos_alpha = 1;
  double delta_in = 0;  // the light's angular radius inside the binder
  double beam = 1;      // light.spectral × beam = irradiance normal to the beam
  double concentration = 0;
  double depth = 0;         // H along the normal, mm
  double surface_area = 0;  // Σ of the tilted surface, mm²
  Uint4 key{};              // (canvas cell, flake orientation cell, seed)
};

namespace {
// Smooth step from 0 at edge0 to 1 at edge1 (GLSL smoothstep).
double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Above this many sparkles in one cell their summed area is drawn at once.
constexpr int kMaxSummedSparkles = 256;

// Index of the orientation cell holding a slope, kept inside int32 for steep normals.
std::uint32_t orientation_cell(double slope, double step) {
  const double q = std::clamp(std::floor(slope / step), -1e9, 1e9);
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(q));
}

}  // namespace

SparkleRenderer::SparkleRenderer(const FlakePaint& paint, std::span<const double> wavelengths_nm,
                                 SparkleSettings settings)
    : tables_(paint, wavelengths_nm), settings_(settings) {
  if (!(settings_.orientation_cell > 0.0)) {
    throw std::runtime_error("sparkle settings: orientation_cell must be positive");
  }
  const double cv = paint.flake_area_sd_mm2 / paint.flake_area_mean_mm2;
  log_area_sd_ = std::sqrt(std::log1p(cv * cv));
  log_area_mean_ = std::log(paint.flake_area_mean_mm2) - 0.5 * log_area_sd_ * log_area_sd_;
}

// The numbered steps are those of the paper's §5.3.5.
bool SparkleRenderer::prepare(const FlakeCell& cell, const Light& light, const View& view,
                              Setup& s) const {
  if (!(cell.flake_concentration > 0.0) || !(cell.thickness_mm > 0.0)) return false;
  if (light.kind == Light::Kind::diffuse) return false;  // every flake a little, none brightly
  check_light(light, tables_.wavelength_count());
  const FlakePaint& paint = tables_.paint();

  // 1–2. Unit directions from the cell to the light and to the viewer, both above the paint.
  Vec3 to_light;
  double beam = 1.0;  // scales light.spectral to the irradiance normal to the beam
  if (light.kind == Light::Kind::directional) {
    to_light = -normalized(light.direction);
  } else {
    const Vec3 d = light.position_mm - cell.center_mm;
    const double distance2 = dot(d, d);
    to_light = (1.0 / std::sqrt(distance2)) * d;
    beam = 1.0 / distance2;
    if (light.kind == Light::Kind::spot) {
      beam *= smoothstep(std::cos(light.spot_outer_rad), std::cos(light.spot_inner_rad),
                         -dot(normalized(light.direction), to_light));
    }
  }
  const Vec3 to_view = view.orthographic ? normalized(view.direction)
                                         : normalized(view.position_mm - cell.center_mm);
  const Vec3 n = cell.normal;
  if (!(n.z > 0.0)) return false;  // a surface facing away from the viewer's side of the canvas
  const double cos_light = dot(n, to_light), cos_view = dot(n, to_view);
  if (!(beam > 0.0) || !(cos_light > 0.0) || !(cos_view > 0.0)) return false;

  // 3–4. Into the binder (Eq. 8), and the flake that mirrors one into the other.
  const double eta = paint.binder_index;
  const Vec3 v_light = refract_into_binder(to_light, n, eta);
  const Vec3 v_view = refract_into_binder(to_view, n, eta);
  const double cos_light_in = cos_inside_binder(cos_light, eta);
  const double cos_view_in = cos_inside_binder(cos_view, eta);
  const SpecularFlake flake = specular_flake(v_view, v_light, n);
  const double density = tables_.orientation_density(flake.cos_beta);
  if (!(density > 0.0)) return false;

  // 5. The light's angular radius inside the binder (Eq. 7).
  s.delta_in = binder_angular_size(0.5 * light.angular_diameter_rad, cos_light, cos_light_in, eta);

  // 7. Expected count (Eq. 5 or 6) among the D·Σ·H flakes of the cell.
  s.concentration = cell.flake_concentration;
  s.depth = cell.thickness_mm * n.z;
  const double flakes = s.concentration * paint.area_density_per_mm / paint.flake_area_mean_mm2 *
                        cell.area_mm2 * cell.thickness_mm;
  const double probability = mirror_probability(density, s.delta_in, flake.cos_alpha);
  s.cos_light = cos_light;
  s.cos_view = cos_view;
  s.cos_light_in = cos_light_in;
  s.cos_view_in = cos_view_in;
  s.cos_alpha = flake.cos_alpha;
  s.mean_count =
      settings_.depth_model == SparkleSettings::DepthModel::with_masking
          ? expected_sparkles_with_masking(flakes, probability)
          : expected_sparkles_without_masking(flakes, probability, optical_thickness(s), s.depth);
  s.beam = beam;
  s.surface_area = cell.area_mm2 / n.z;

  const double step = settings_.orientation_cell;
  s.key = {
      static_cast<std::uint32_t>(cell.ix), static_cast<std::uint32_t>(cell.iy),
      orientation_cell(flake.normal.x / flake.normal.z, step),
      orientation_cell(flake.normal.y / flake.normal.z, step) ^ (settings_.seed * 0x9E3779B9u)};
  return s.mean_count > 0.0;
}

// 6. Optical thickness per unit depth of the way in and out, 1/mm (flakes and their pigment
// scale with the concentration in the cell, the binder's absorption does not).
double SparkleRenderer::optical_thickness(const Setup& s) const {
  const FlakePaint& paint = tables_.paint();
  const double c = s.concentration;
  auto one_way = [&](double cos_in) {
    return optical_thickness_per_depth(
        c * paint.area_density_per_mm, tables_.projected_area(cos_in),
        tables_.projected_transmittance(cos_in), paint.binder_absorption_per_mm,
        c * paint.rayleigh_weight_per_mm, cos_in);
  };
  return one_way(s.cos_light_in) + one_way(s.cos_view_in);
}

// Eqs. 9–10 per unit flake area and unit light.spectral, spread over the cell's surface.
double SparkleRenderer::radiance_per_area(const Setup& s) const {
  const double eta = tables_.paint().binder_index;
  const double energy = sparkle_energy_per_area(
      s.beam * s.cos_light, s.cos_light_in, 1.0 - fresnel_dielectric(s.cos_light, eta),
      1.0 - fresnel_dielectric(s.cos_view, eta), 1.0, s.cos_alpha);
  return visible_radiance(energy, s.delta_in, eta, s.cos_view_in, s.surface_area);
}

double SparkleRenderer::expected_count(const FlakeCell& cell, const Light& light,
                                       const View& view) const {
  Setup s;
  return prepare(cell, light, view, s) ? s.mean_count : 0.0;
}

double SparkleRenderer::flake_weight(CounterRng& rng, int count, double t_per_depth,
                                     double depth) const {
  const bool attenuated = settings_.depth_model == SparkleSettings::DepthModel::with_masking;
  const FlakePaint& paint = tables_.paint();
  if (count > kMaxSummedSparkles) {
    // Many sparkles (a footprint of many cells): the sum by the central limit theorem, with
    // the exact mean and variance of one sparkle's S·e^{−tz}.
    const double mean_s = paint.flake_area_mean_mm2, sd_s = paint.flake_area_sd_mm2;
    const double a1 = attenuated ? direct_fraction(t_per_depth, depth) : 1.0;
    const double a2 = attenuated ? direct_fraction(2.0 * t_per_depth, depth) : 1.0;
    const double mean = mean_s * a1;
    const double variance = std::max(0.0, (sd_s * sd_s + mean_s * mean_s) * a2 - mean * mean);
    return std::max(0.0, count * mean + std::sqrt(count * variance) * rng.normal());
  }
  double sum = 0;
  for (int i = 0; i < count; ++i) {
    const double area = log_area_sd_ > 0.0 ? std::exp(log_area_mean_ + log_area_sd_ * rng.normal())
                                           : paint.flake_area_mean_mm2;
    // With masking the sparkle lies at a depth uniform in [0, H] and its light is dimmed.
    sum += attenuated ? area * std::exp(-t_per_depth * depth * rng.uniform()) : area;
  }
  return sum;
}

int SparkleRenderer::add_cell(const FlakeCell& cell, const Light& light, const View& view,
                              std::span<double> radiance) const {
  Setup s;
  if (!prepare(cell, light, view, s)) return 0;
  CounterRng rng(s.key);
  const int count = sample_sparkle_count(rng, s.mean_count);
  if (count == 0) return 0;
  const double scale =
      radiance_per_area(s) * flake_weight(rng, count, optical_thickness(s), s.depth);
  for (std::size_t w = 0; w < radiance.size(); ++w) {
    radiance[w] += scale * light.spectral[w] * tables_.flake_reflectance(w, s.cos_alpha);
  }
  return count;
}

void SparkleRenderer::add_mean_radiance(const FlakeCell& cell, const Light& light, const View& view,
                                        std::span<double> radiance) const {
  Setup s;
  if (!prepare(cell, light, view, s)) return;
  double mean_weight = tables_.paint().flake_area_mean_mm2;
  if (settings_.depth_model == SparkleSettings::DepthModel::with_masking) {
    // ⟨e^{−tz}⟩ over z uniform in [0, H]
    mean_weight *= direct_fraction(optical_thickness(s), s.depth);
  }
  const double scale = s.mean_count * mean_weight * radiance_per_area(s);
  for (std::size_t w = 0; w < radiance.size(); ++w) {
    radiance[w] += scale * light.spectral[w] * tables_.flake_reflectance(w, s.cos_alpha);
  }
}

}  // namespace impasto::flakes
