#include "impasto/render/surface_shading.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <tuple>

namespace impasto::render {
namespace {

constexpr double kDegreesToRadians = std::numbers::pi / 180.0;

// BRDF tables by their parameters: renderers for the same light and surface share them
// (the window rebuilds its renderer on every settings change; a table takes ~20 ms).
std::shared_ptr<const surface::GhsBrdf> shared_brdf(const surface::GhsParams& p) {
  using Key = std::tuple<double, double, double, double, double, double, bool>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const surface::GhsBrdf>> cache;
  const Key key{p.roughness.rms_um, p.roughness.correlation_um, p.wavelength_nm, p.index,
                p.source_sigma,     p.subcell_slope_rms,        p.fresnel};
  {
    std::lock_guard lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  auto made = std::make_shared<const surface::GhsBrdf>(p);
  std::lock_guard lock(mutex);
  if (cache.size() > 512) cache.clear();  // bounded: a session tries few surfaces
  return cache.emplace(key, std::move(made)).first->second;
}

// The dried paint's surface: tube paint (satin) and the medium's finish mixed by the amount
// of medium, geometrically (roughness spans decades).
surface::Roughness paint_roughness(const SurfaceSettings& s) {
  const surface::Roughness tube = surface::finish_roughness(surface::Finish::satin);
  const surface::Roughness medium = surface::finish_roughness(s.medium);
  const double a = s.medium_amount;
  return {std::pow(tube.rms_um, 1.0 - a) * std::pow(medium.rms_um, a),
          std::pow(tube.correlation_um, 1.0 - a) * std::pow(medium.correlation_um, a)};
}

// 2 ∫ F(μ) μ dμ: the smooth surface's reflectance of uniform sky light.
double hemispherical_fresnel(double n) {
  constexpr int kSteps = 512;
  double sum = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    const double mu = (k + 0.5) / kSteps;
    sum += surface::fresnel_dielectric(mu, n) * mu;
  }
  return 2.0 * sum / kSteps;
}

}  // namespace

std::unique_ptr<SurfaceShading> SurfaceShading::create(const RenderSettings& settings,
                                                       const SpectralPalette& palette) {
  if (settings.surface.model != SurfaceModel::ghs) return nullptr;
  return std::make_unique<SurfaceShading>(settings, palette);
}

SurfaceShading::SurfaceShading(const RenderSettings& settings, const SpectralPalette& palette)
    : nodes_(palette.nodes()),
      ambient_(static_cast<float>(settings.ambient)),
      reflection_(settings.surface.reflection) {
  const SurfaceSettings& s = settings.surface;
  const int nodes = palette.nodes();
  const auto count = static_cast<std::size_t>(nodes);
  wavelengths_.assign(palette.sampling().wavelengths_nm.begin(),
                      palette.sampling().wavelengths_nm.begin() + nodes);
  subcell_slope_rms_ = s.subcell_slope_rms;
  binder_index_ = s.binder_index;
  varnish_index_ = s.varnish_index;
  settings_varnish_ = s.varnish.has_value();
  default_log_rms_ = std::log10(paint_roughness(s).rms_um);
  dry_.resize(count);
  wet_.resize(count);
  reference_.resize(count);
  reference_sky_.resize(count);
  for (int c = 0; c < 3; ++c) {
    to_xyz_[static_cast<std::size_t>(c)].assign(palette.to_display_xyz(c),
                                                palette.to_display_xyz(c) + nodes);
  }
  // The light's disc (the shadows' diameter, so a highlight is as soft as a penumbra) as a
  // Gaussian in direction cosines: a disc of radius a has a/2 per axis.
  const double source_sigma = 0.25 * settings.shadow_light_diameter_deg * kDegreesToRadians;
  source_sigma_ = source_sigma;
  const double flat_mu = std::max(std::sin(settings.light_elevation_deg * kDegreesToRadians),
                                  0.05);  // as Blinn-Phong's
  tbb::parallel_for(0, nodes, [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    const double wavelength = palette.sampling().wavelengths_nm[k];
    surface::GhsParams dry;
    dry.wavelength_nm = wavelength;
    dry.source_sigma = source_sigma;
    dry.subcell_slope_rms = s.subcell_slope_rms;
    surface::GhsParams wet = dry;
    dry.roughness = s.varnish ? surface::finish_roughness(*s.varnish) : paint_roughness(s);
    dry.index = surface::binder_index(wavelength, s.varnish ? s.varnish_index : s.binder_index);
    wet.roughness = surface::finish_roughness(surface::Finish::gloss);
    wet.index = surface::binder_index(wavelength, s.binder_index);
    dry_[k] = shared_brdf(dry);
    wet_[k] = shared_brdf(wet);
    const double n = wet.index;
    const double view = 1.0 - surface::fresnel_dielectric(1.0, n);
    reference_[k] = static_cast<float>((1.0 - surface::fresnel_dielectric(flat_mu, n)) * view);
    reference_sky_[k] = static_cast<float>((1.0 - hemispherical_fresnel(n)) * view);
  });
}

int SurfaceShading::level_of(double log_rms) {
  const double k = std::round((log_rms - paintcore::kMinLogRms) / kLevelStep);
  if (!(k >= 0.0)) return 0;  // NaN too (a cast of NaN to int is undefined)
  return static_cast<int>(std::min(k, static_cast<double>(kLevels - 1)));
}

double SurfaceShading::level_log_rms(int level) {
  return paintcore::kMinLogRms + level * kLevelStep;
}

const SurfaceShading::Brdfs& SurfaceShading::level_brdfs(bool varnish, int level) const {
  const int k = std::clamp(level, 0, kLevels - 1);
  const auto slot = static_cast<std::size_t>((varnish ? kLevels : 0) + k);
  std::call_once(level_made_[slot], [&] {
    Brdfs made(wavelengths_.size());
    // Isolated: a worker waiting here must not pick up another cell's call for this level.
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(std::size_t{0}, made.size(), [&](std::size_t i) {
        surface::GhsParams p;
        p.wavelength_nm = wavelengths_[i];
        p.source_sigma = source_sigma_;
        p.subcell_slope_rms = subcell_slope_rms_;
        p.roughness = surface::roughness_at_log_rms(level_log_rms(k));
        p.index = surface::binder_index(wavelengths_[i], varnish ? varnish_index_ : binder_index_);
        made[i] = shared_brdf(p);
      });
    });
    levels_[slot] = std::move(made);
  });
  return levels_[slot];
}

void SurfaceShading::shade(shade::Vec3 normal, shade::Vec3 to_light, shade::Visibility visibility,
                           float wetness, const float* reflectance, float xyz[3]) const {
  shade_on(dry_, normal, to_light, visibility, wetness, reflectance, xyz);
}

void SurfaceShading::shade(shade::Vec3 normal, shade::Vec3 to_light, shade::Visibility visibility,
                           float wetness, const paintcore::CellSurface& cell,
                           const float* reflectance, float xyz[3]) const {
  const CellDry dry = cell_dry(cell);
  if (dry.level < 0) {
    shade_on(dry_, normal, to_light, visibility, wetness, reflectance, xyz);
  } else {
    const float w = std::max(wetness > 0.0f ? wetness : 0.0f, dry.min_wetness);
    shade_on(level_brdfs(dry.varnish, dry.level), normal, to_light, visibility, w, reflectance,
             xyz);
  }
}

SurfaceShading::CellDry SurfaceShading::cell_dry(const paintcore::CellSurface& cell) const {
  if (cell.varnished()) {
    // A varnish is a liquid when it goes on: glossy (the wet surface) until it dries.
    return {true, level_of(cell.varnish_log_rms), cell.varnish_wetness()};
  }
  if (cell.medium.share > 0.0f && !settings_varnish_) {
    const double share = std::min(cell.medium.share, 1.0f);
    const double log_rms = share * cell.medium.log_rms + (1.0 - share) * default_log_rms_;
    return {false, level_of(log_rms), 0.0f};
  }
  return {};
}

void SurfaceShading::shade_on(const Brdfs& dry_brdfs, shade::Vec3 normal, shade::Vec3 to_light,
                              shade::Visibility visibility, float wetness, const float* reflectance,
                              float xyz[3]) const {
  const float w = wetness > 0.0f ? std::min(wetness, 1.0f) : 0.0f;  // NaN: dry
  const float mu_i = shade::dot(normal, to_light);
  const float mu_v = normal.z;  // the viewer straight above
  const float flat_lambert = std::max(to_light.z, 0.05f);
  const float lit = std::max(mu_i, 0.0f);
  const float direct =
      visibility.shadow * (1.0f - shade::kOcclusionDirectShare * (1.0f - visibility.occlusion));
  // The half-way geometry: |tangential part of l + v| and the Fresnel angle's cosine.
  const shade::Vec3 sum{to_light.x, to_light.y, to_light.z + 1.0f};
  const float sum2 = shade::dot(sum, sum);
  const float along = shade::dot(normal, sum);
  const double rho = std::sqrt(std::max(0.0f, sum2 - along * along));
  const double cos_half = (1.0f + to_light.z) / std::sqrt(sum2);
  const float sky = ambient_ * visibility.occlusion;
  const float sun = (1.0f - ambient_);
  const int nodes = nodes_;
  thread_local std::vector<float> values;  // nodes, or every nm of the full spectrum
  values.resize(static_cast<std::size_t>(nodes));
  float* value = values.data();
  for (int i = 0; i < nodes; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const surface::GhsBrdf& dry = *dry_brdfs[k];
    const surface::GhsBrdf& wet = *wet_[k];
    const auto mix = [w](double a, double b) { return static_cast<float>(a + w * (b - a)); };
    const float albedo_in = mu_i > 0.0f ? mix(dry.albedo(mu_i), wet.albedo(mu_i)) : 0.0f;
    const float albedo_view = mix(dry.albedo(mu_v), wet.albedo(mu_v));
    const float albedo_sky = mix(dry.hemispherical_albedo(), wet.hemispherical_albedo());
    const float exit = 1.0f - albedo_view;
    const float body =
        sky * (1.0f - albedo_sky) * exit / reference_sky_[k] +
        sun * (lit / flat_lambert) * direct * (1.0f - albedo_in) * exit / reference_[k];
    float specular = 0.0f;
    if (reflection_) {
      float f = 0.0f;
      if (mu_i > 0.0f) {
        const double f_dry = w < 1.0f ? dry.eval(mu_i, mu_v, rho, cos_half) : 0.0;
        const double f_wet = w > 0.0f ? wet.eval(mu_i, mu_v, rho, cos_half) : 0.0;
        f = mix(f_dry, f_wet);
      }
      // π f cos θ_i against the white Lambertian's cos θ_flat: the units of the body above.
      specular = sun * visibility.shadow * std::numbers::pi_v<float> * f * lit / flat_lambert +
                 sky * albedo_view;
    }
    value[i] = reflectance[i] * body + specular;
  }
  for (int c = 0; c < 3; ++c) {
    const float* weights = to_xyz_[static_cast<std::size_t>(c)].data();
    float total = 0.0f;
    for (int i = 0; i < nodes; ++i) total += weights[i] * value[i];
    xyz[c] = total;
  }
}

}  // namespace impasto::render
