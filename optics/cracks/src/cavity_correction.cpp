#include "impasto/cracks/cavity_correction.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <tuple>

namespace impasto::cracks {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kAzimuths = 64;  // midpoints over a quarter turn (|cos| repeats)

// d of the beam tables at zenith z, linear between the measured zeniths (the last beyond).
void add_beam(std::span<float> out, std::size_t shape_offset, std::size_t count, double zenith_deg,
              double weight) {
  const auto& zeniths = kShippedBeamZenithsDeg;
  const double z = std::clamp(zenith_deg, zeniths.front(), zeniths.back());
  std::size_t k = 0;
  while (k + 2 < zeniths.size() && z > zeniths[k + 1]) ++k;
  const double f = (z - zeniths[k]) / (zeniths[k + 1] - zeniths[k]);
  const auto& a = shipped_beam_table(static_cast<int>(k)).differences();
  const auto& b = shipped_beam_table(static_cast<int>(k + 1)).differences();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = shape_offset + i;
    out[at] += static_cast<float>(weight * ((1.0 - f) * a[at] + f * b[at]));
  }
}

}  // namespace

CavityCorrection::CavityCorrection(const CrackSceneLight& light)
    : light_(light), grid_(shipped_cavity_table().grid()) {
  const double s = std::clamp(light.sky_share, 0.0, 1.0);
  const double sun = std::clamp(light.sun_zenith_deg, 0.0, 90.0);
  const std::size_t per_shape =
      static_cast<std::size_t>(grid_.ratio_count) * static_cast<std::size_t>(grid_.rho0_count);
  differences_.assign(kAllShapes.size() * per_shape, 0.0f);
  const auto& sky = shipped_sky_table().differences();
  for (CavityShape shape : kAllShapes) {
    const std::size_t offset = static_cast<std::size_t>(shape) * per_shape;
    if (s < 1.0) {
      if (is_groove(shape) && light.average_groove_azimuth) {
        for (int a = 0; a < kAzimuths; ++a) {
          const double azimuth = (a + 0.5) * 0.5 * std::numbers::pi / kAzimuths;
          const double projected = std::atan(std::tan(sun * kDegree) * std::cos(azimuth)) / kDegree;
          add_beam(differences_, offset, per_shape, projected, (1.0 - s) / kAzimuths);
        }
      } else {
        add_beam(differences_, offset, per_shape, sun, 1.0 - s);
      }
    }
    for (std::size_t i = 0; i < per_shape && s > 0.0; ++i) {
      differences_[offset + i] += static_cast<float>(s * sky[offset + i]);
    }
  }
}

double CavityCorrection::reflectance_at(CavityShape shape, double u, const ViewFactors& vf,
                                        double rho0) const {
  return CavityTable::clamp_to_walls(
      apparent_reflectance(rho0, vf) +
          interpolate_difference(grid_, differences_, shape, u, rho0, vf),
      rho0);
}

std::shared_ptr<const CavityCorrection> cavity_correction(const CrackSceneLight& light) {
  // A render asks once per tile; a session sees a handful of lights, or a stream of them
  // while the light is dragged, so the cache starts again rather than grow past 32.
  static std::mutex mutex;
  static std::map<std::tuple<double, double, bool>, std::shared_ptr<const CavityCorrection>> cache;
  const auto key =
      std::make_tuple(light.sun_zenith_deg, light.sky_share, light.average_groove_azimuth);
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(key); found != cache.end()) return found->second;
  if (cache.size() >= 32) cache.clear();
  auto made = std::make_shared<const CavityCorrection>(light);
  cache.emplace(key, made);
  return made;
}

double cavity_reflectance(CavityModel model, CavityShape shape, const CavityDims& dims,
                          const ViewFactors& vf, double rho0, const CrackSceneLight& light) {
  if (model == CavityModel::Gouffe) return apparent_reflectance(rho0, vf);
  const std::shared_ptr<const CavityCorrection> correction = cavity_correction(light);
  return correction->reflectance_at(
      shape, correction->ratio_coordinate(dims.depth_mm / dims.half_width_mm), vf, rho0);
}

}  // namespace impasto::cracks
