#include "impasto/render/flake_shading.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impasto/flakes/flake_file.hpp"

namespace impasto::render {

using paintcore::kTileCells;

namespace {

constexpr double kDegreesToRadians = std::numbers::pi / 180.0;

// The viewer looks straight down on the canvas, as in shade::blinn_phong.
const flakes::View kView{true, {0.0, 0.0, 1.0}, {}};

bool any_positive(const float* amounts) {
  return std::any_of(amounts, amounts + kTileCells, [](float a) { return a > 0.0f; });
}

}  // namespace

flakes::Light sparkle_light(const RenderSettings& settings, double canvas_width_mm,
                            double canvas_height_mm, int nodes) {
  // The same direction (in float) as the renderer's Blinn-Phong term.
  const shade::Vec3 to =
      shade::light_direction(static_cast<float>(settings.light_azimuth_deg * kDegreesToRadians),
                             static_cast<float>(settings.light_elevation_deg * kDegreesToRadians));
  const flakes::Vec3 to_light{to.x, to.y, to.z};
  // A flat white Lambertian surface under irradiance E⊥·cos θ′ has radiance E⊥ cos θ′ / π;
  // the renderer shows it as (1 − ambient) · lambert with lambert = 1 when flat.
  const double strength =
      (1.0 - settings.ambient) * std::numbers::pi / std::max(static_cast<double>(to.z), 0.05);

  flakes::Light light;
  light.angular_diameter_rad = settings.light_size_deg * kDegreesToRadians;
  const double distance = settings.light_distance_mm;
  const flakes::Vec3 centre{0.5 * canvas_width_mm, 0.5 * canvas_height_mm, 0.0};
  switch (settings.light_type) {
    case LightType::directional:
      light.kind = flakes::Light::Kind::directional;
      light.direction = -to_light;
      light.spectral.assign(static_cast<std::size_t>(nodes), strength);
      break;
    case LightType::point:
    case LightType::spot:
      light.kind = settings.light_type == LightType::point ? flakes::Light::Kind::point
                                                           : flakes::Light::Kind::spot;
      light.position_mm = centre + distance * to_light;
      light.direction = -to_light;
      light.spot_outer_rad = settings.spot_angle_deg * kDegreesToRadians;
      light.spot_inner_rad = 0.8 * light.spot_outer_rad;
      // Intensity: the directional strength at the canvas centre (irradiance = I / d²).
      light.spectral.assign(static_cast<std::size_t>(nodes), strength * distance * distance);
      break;
    case LightType::diffuse:
      light.kind = flakes::Light::Kind::diffuse;
      light.spectral.assign(static_cast<std::size_t>(nodes), 0.0);
      break;
  }
  return light;
}

std::unique_ptr<FlakeShading> FlakeShading::create(const RenderSettings& settings,
                                                   const SpectralPalette& palette) {
  if (!settings.flakes || settings.light_type == LightType::diffuse) return nullptr;
  bool any = false;
  for (int p = 0; p < palette.pigment_count(); ++p) any = any || !palette.flake_file(p).empty();
  if (!any) return nullptr;
  return std::unique_ptr<FlakeShading>(new FlakeShading(settings, palette));
}

FlakeShading::FlakeShading(const RenderSettings& settings, const SpectralPalette& palette)
    : settings_(settings), nodes_(palette.nodes()) {
  const std::vector<double> wavelengths(palette.sampling().wavelengths_nm.begin(),
                                        palette.sampling().wavelengths_nm.end());
  flakes::SparkleSettings sparkle_settings;
  sparkle_settings.depth_model = settings.flake_masking
                                     ? flakes::SparkleSettings::DepthModel::with_masking
                                     : flakes::SparkleSettings::DepthModel::without_masking;
  for (int p = 0; p < palette.pigment_count(); ++p) {
    const std::filesystem::path& file = palette.flake_file(p);
    if (file.empty()) continue;
    pigments_.push_back({p, flakes::SparkleRenderer(flakes::load_flake_paint(file), wavelengths,
                                                    sparkle_settings)});
  }
  const auto n = static_cast<std::size_t>(nodes_);
  to_xyz_.resize(3 * n);
  for (int c = 0; c < 3; ++c) {
    std::copy_n(palette.to_display_xyz(c), n, to_xyz_.begin() + static_cast<std::ptrdiff_t>(c * n));
  }
}

void FlakeShading::add_xyz(const double* node_radiance, float xyz[3]) const {
  const auto n = static_cast<std::size_t>(nodes_);
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += to_xyz_[c * n + i] * node_radiance[i];
    xyz[c] += static_cast<float>(sum);
  }
}

FlakeTileView FlakeShading::tile(const paintcore::Canvas& canvas, int tile_index) const {
  FlakeTileView view;
  bool any = false;
  if (const paintcore::Tile* wet = canvas.tile(tile_index)) {
    for (std::size_t k = 0; k < pigments_.size(); ++k) {
      const float* amounts = wet->pigment(pigments_[k].slot);
      if (amounts != nullptr && any_positive(amounts)) {
        view.wet_[k] = amounts;
        any = true;
      }
    }
  }
  const auto& layers = canvas.dry_layers();
  for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
    const paintcore::DryTile* dry = layer->find(tile_index);
    if (dry == nullptr) continue;
    FlakeTileView::DryLayer entry{dry->volume_mm.data(), {}};
    for (std::size_t k = 0; k < pigments_.size(); ++k) {
      entry.amounts[k] = dry->pigment(pigments_[k].slot);  // only slots with paint are kept
      any = any || entry.amounts[k] != nullptr;
    }
    view.dry_.push_back(entry);
  }
  if (!any) return {};

  view.shading_ = this;
  view.cell_mm_ = canvas.cell_mm();
  view.light_ = sparkle_light(settings_, canvas.width_cells() * view.cell_mm_,
                              canvas.height_cells() * view.cell_mm_, nodes_);
  view.radiance_.assign(static_cast<std::size_t>(nodes_), 0.0);
  return view;
}

float FlakeTileView::top_layer(int cell, float wet_volume_mm,
                               std::span<float> concentrations) const {
  const auto c = static_cast<std::size_t>(cell);
  float volume = wet_volume_mm;
  const Amounts* amounts = &wet_;
  if (!(volume > 0.0f)) {
    amounts = nullptr;
    for (const DryLayer& layer : dry_) {
      if (layer.volume_mm[c] > 0.0f) {
        volume = layer.volume_mm[c];
        amounts = &layer.amounts;
        break;
      }
    }
  }
  for (std::size_t k = 0; k < concentrations.size(); ++k) {
    const float* layer_amounts = amounts != nullptr ? (*amounts)[k] : nullptr;
    concentrations[k] =
        layer_amounts != nullptr && layer_amounts[c] > 0.0f ? layer_amounts[c] / volume : 0.0f;
  }
  return amounts != nullptr ? volume : 0.0f;
}

int FlakeTileView::add_cell(int cell, int canvas_x, int canvas_y, shade::Vec3 normal,
                            float surface_height_mm, float wet_volume_mm, float xyz[3]) {
  ++cells_evaluated_;
  const auto& pigments = shading_->pigments();
  std::array<float, kMaxFlakePigments> concentrations{};
  const float thickness =
      top_layer(cell, wet_volume_mm, std::span(concentrations.data(), pigments.size()));
  if (!(thickness > 0.0f)) return 0;  // bare canvas

  int sparkles = 0;
  for (std::size_t k = 0; k < pigments.size(); ++k) {
    if (!(concentrations[k] > 0.0f)) continue;
    flakes::FlakeCell flake_cell;
    flake_cell.ix = canvas_x;
    flake_cell.iy = canvas_y;
    flake_cell.center_mm = {(canvas_x + 0.5) * cell_mm_, (canvas_y + 0.5) * cell_mm_,
                            surface_height_mm};
    flake_cell.normal = {normal.x, normal.y, normal.z};
    flake_cell.area_mm2 = cell_mm_ * cell_mm_;
    flake_cell.flake_concentration = concentrations[k];
    flake_cell.thickness_mm = thickness;
    sparkles += pigments[k].sparkles.add_cell(flake_cell, light_, kView, radiance_);
  }
  if (sparkles > 0) {
    shading_->add_xyz(radiance_.data(), xyz);
    std::fill(radiance_.begin(), radiance_.end(), 0.0);
  }
  return sparkles;
}

}  // namespace impasto::render
