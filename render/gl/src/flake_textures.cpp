#include "impasto/render_gl/flake_textures.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace impasto::render_gl {

using flakes::FlakeTables;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr int kTableWidth = FlakeTables::kOrientationSamples;
constexpr int kRowsPerPigment = 3 + render::kMaxNodes;  // FLAKE_ROWS in flakes_lib.glsl

}  // namespace

FlakeTextures::FlakeTextures(int width_cells, int height_cells,
                             const render::RenderSettings& settings,
                             const render::SpectralPalette& palette)
    : width_(width_cells),
      height_(height_cells),
      shading_(render::FlakeShading::create(settings, palette)) {
  if (!shading_) return;
  const auto& pigments = shading_->pigments();
  if (pigments.size() > static_cast<std::size_t>(kMaxFlakePigments)) {
    throw std::runtime_error("GPU renderer: " + std::to_string(pigments.size()) +
                             " flake pigments; the shaders take at most " +
                             std::to_string(kMaxFlakePigments));
  }
  const int nodes = palette.nodes();
  node_to_xyz_.resize(static_cast<std::size_t>(3 * nodes));
  for (int n = 0; n < nodes; ++n) {
    for (int c = 0; c < 3; ++c) {
      node_to_xyz_[static_cast<std::size_t>(3 * n + c)] = palette.to_display_xyz(c)[n];
    }
  }

  const int rows = kRowsPerPigment * static_cast<int>(pigments.size());
  std::vector<float> texels(static_cast<std::size_t>(kTableWidth) * static_cast<std::size_t>(rows),
                            0.0f);
  auto put_row = [&](int row, auto&& samples) {
    std::transform(samples.begin(), samples.end(),
                   texels.begin() + static_cast<std::ptrdiff_t>(row) * kTableWidth,
                   [](double v) { return static_cast<float>(v); });
  };
  for (std::size_t f = 0; f < pigments.size(); ++f) {
    const FlakeTables& tables = pigments[f].sparkles.tables();
    const int base = static_cast<int>(f) * kRowsPerPigment;
    put_row(base, tables.orientation_samples());
    put_row(base + 1, tables.projected_area_samples());
    put_row(base + 2, tables.projected_transmittance_samples());
    for (int n = 0; n < nodes; ++n) {
      put_row(base + 3 + n, tables.reflectance_samples(static_cast<std::size_t>(n)));
    }
  }
  tables_ = Texture(kTableWidth, rows, 0, TexelFormat::kR32F);
  tables_.upload(0, 0, kTableWidth, rows, 0, texels.data(), kTableWidth);
}

void FlakeTextures::upload_tile(const paintcore::Canvas& canvas, int tile_index) {
  if (!shading_) return;
  const render::FlakeTileView view = shading_->tile(canvas, tile_index);
  if (!view.active() && layer_.id() == 0) return;  // no flake paint anywhere yet
  if (layer_.id() == 0) {
    layer_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
    const std::vector<float> zeros(4 * static_cast<std::size_t>(width_) * height_, 0.0f);
    layer_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
  }

  const int x0 = (tile_index % canvas.tiles_x()) * kTileSize;
  const int y0 = (tile_index / canvas.tiles_x()) * kTileSize;
  const int w = std::min(kTileSize, width_ - x0);
  const int h = std::min(kTileSize, height_ - y0);
  scratch_.assign(4 * static_cast<std::size_t>(kTileCells), 0.0f);
  const paintcore::Tile* tile = canvas.tile(tile_index);
  if (view.active()) {
    const std::size_t count = shading_->pigments().size();
    for (int cell = 0; cell < kTileCells; ++cell) {
      float* texel = &scratch_[4 * static_cast<std::size_t>(cell)];
      const float wet =
          tile != nullptr ? tile->wet_volume_mm[static_cast<std::size_t>(cell)] : 0.0f;
      texel[0] = view.top_layer(cell, wet, std::span(texel + 1, count));
    }
  }
  layer_.upload(x0, y0, w, h, 0, scratch_.data(), kTileSize);
}

void FlakeTextures::bind(const ShaderProgram& program, const render::RenderSettings& settings,
                         double cell_mm) const {
  const bool on = shading_ && layer_.id() != 0;
  glUniform1i(program.uniform("flake_layer"), kLayerUnit);
  glUniform1i(program.uniform("flake_tables"), kTablesUnit);
  glUniform1i(program.uniform("flake_count"),
              on ? static_cast<GLint>(shading_->pigments().size()) : 0);
  if (!on) return;
  layer_.bind(kLayerUnit);
  tables_.bind(kTablesUnit);

  std::vector<float> paint, paint2;
  for (const auto& pigment : shading_->pigments()) {
    const flakes::FlakePaint& p = pigment.sparkles.tables().paint();
    paint.insert(
        paint.end(),
        {static_cast<float>(p.area_density_per_mm), static_cast<float>(p.flake_area_mean_mm2),
         static_cast<float>(p.binder_index), static_cast<float>(p.binder_absorption_per_mm)});
    paint2.insert(paint2.end(), {static_cast<float>(p.rayleigh_weight_per_mm),
                                 static_cast<float>(pigment.sparkles.log_area_mean()),
                                 static_cast<float>(pigment.sparkles.log_area_sd()),
                                 static_cast<float>(p.flake_area_sd_mm2)});
  }
  const auto count = static_cast<GLsizei>(shading_->pigments().size());
  glUniform4fv(program.uniform("flake_paint"), count, paint.data());
  glUniform4fv(program.uniform("flake_paint2"), count, paint2.data());

  const auto& sparkle_settings = shading_->pigments().front().sparkles.settings();
  glUniform1f(program.uniform("flake_orientation_cell"),
              static_cast<float>(sparkle_settings.orientation_cell));
  glUniform1ui(program.uniform("flake_seed"), sparkle_settings.seed);
  glUniform1i(program.uniform("flake_masking"),
              sparkle_settings.depth_model == flakes::SparkleSettings::DepthModel::with_masking);

  const flakes::Light light =
      render::sparkle_light(settings, width_ * cell_mm, height_ * cell_mm, shading_->nodes());
  const int kind = light.kind == flakes::Light::Kind::directional ? 0
                   : light.kind == flakes::Light::Kind::point     ? 1
                                                                  : 2;
  glUniform1i(program.uniform("flake_light_kind"), kind);
  glUniform3f(program.uniform("flake_light_direction"), static_cast<float>(light.direction.x),
              static_cast<float>(light.direction.y), static_cast<float>(light.direction.z));
  glUniform3f(program.uniform("flake_light_position"), static_cast<float>(light.position_mm.x),
              static_cast<float>(light.position_mm.y), static_cast<float>(light.position_mm.z));
  glUniform1f(program.uniform("flake_light_diameter"),
              static_cast<float>(light.angular_diameter_rad));
  glUniform2f(program.uniform("flake_spot_cos"), static_cast<float>(std::cos(light.spot_outer_rad)),
              static_cast<float>(std::cos(light.spot_inner_rad)));
  glUniform1f(program.uniform("flake_light_strength"), static_cast<float>(light.spectral.front()));
  glUniform1i(program.uniform("flake_nodes"), shading_->nodes());
  glUniform3fv(program.uniform("flake_node_to_xyz"), shading_->nodes(), node_to_xyz_.data());
  glUniform1f(program.uniform("flake_cell_mm"), static_cast<float>(cell_mm));
}

}  // namespace impasto::render_gl
