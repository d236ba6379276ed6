#include "impasto/render_gl/crack_texture.hpp"

#include <algorithm>

#include <cmath>
#include <numbers>

#include "impasto/render/crack_close_up.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/shading.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;
using paintcore::kTileSize;

void CrackTexture::upload_tile(const paintcore::Canvas& canvas, int tile_index) {
  const paintcore::CrackTile* tile = canvas.cracks().tile(tile_index);
  if (tile == nullptr && cells_.id() == 0) return;  // no crack anywhere yet
  if (cells_.id() == 0) {
    cells_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
    shapes_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
    const std::vector<float> zeros(4 * static_cast<std::size_t>(width_) * height_, 0.0f);
    cells_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
    shapes_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
  }
  const int x0 = (tile_index % canvas.tiles_x()) * kTileSize;
  const int y0 = (tile_index / canvas.tiles_x()) * kTileSize;
  const int w = std::min(kTileSize, width_ - x0);
  const int h = std::min(kTileSize, height_ - y0);
  scratch_.assign(4 * static_cast<std::size_t>(kTileCells), 0.0f);
  shape_scratch_.assign(4 * static_cast<std::size_t>(kTileCells), 0.0f);
  for (int cell = 0; tile != nullptr && cell < kTileCells; ++cell) {
    const paintcore::CrackRecord& record = tile->cells[static_cast<std::size_t>(cell)];
    if (!record.has_crack()) continue;
    const render::CrackOptics optics = render::crack_optics(record, canvas.cell_mm());
    float* texel = &scratch_[4 * static_cast<std::size_t>(cell)];
    texel[0] = optics.coverage;
    texel[1] = optics.F;
    texel[2] = optics.G;
    const float packed =
        1.0f + static_cast<float>(optics.shape) * kTableStride + (optics.table_u + 1.0f);
    texel[3] = optics.exposes_ground ? packed : -packed;
    // The close-up's cavity, and the bare canvas's normal its ground-coloured walls are shaded
    // with (as the CPU shades the bare canvas: central differences, edges clamped).
    const int x = x0 + cell % kTileSize, y = y0 + cell / kTileSize;
    const auto base = [&](int cx, int cy) {
      return canvas.base_height_mm(std::clamp(cx, 0, width_ - 1), std::clamp(cy, 0, height_ - 1));
    };
    const render::shade::Vec3 normal =
        render::shade::height_normal(base(x - 1, y), base(x + 1, y), base(x, y - 1), base(x, y + 1),
                                     static_cast<float>(canvas.cell_mm()));
    float* shape = &shape_scratch_[4 * static_cast<std::size_t>(cell)];
    shape[0] = record.depth_mm;
    shape[1] = record.half_width_mm;
    shape[2] = normal.x;
    shape[3] = normal.y;
  }
  cells_.upload(x0, y0, w, h, 0, scratch_.data(), kTileSize);
  shapes_.upload(x0, y0, w, h, 0, shape_scratch_.data(), kTileSize);
}

void CrackTexture::prepare(const render::RenderSettings& settings) {
  if (!settings.cracks || cells_.id() == 0) return;
  // The correction blended for this light, uploaded again only when the light changes.
  const auto [zenith, sky] = render::crack_table_data_light(settings);
  if (table_.id() != 0 && zenith == table_data_.sun_zenith_deg && sky == table_data_.sky_share) {
    return;
  }
  table_data_ = render::crack_table_data(settings);
  const int rows = table_data_.ratio_count * static_cast<int>(table_data_.last_F.size());
  if (table_.id() == 0) table_ = Texture(table_data_.rho0_count, rows, 0, TexelFormat::kR32F);
  table_.upload(0, 0, table_data_.rho0_count, rows, 0, table_data_.differences.data(),
                table_data_.rho0_count);
}

void CrackTexture::bind(const ShaderProgram& program, const render::SpectralPalette& palette,
                        const render::RenderSettings& settings) const {
  const bool on = settings.cracks && cells_.id() != 0;
  glUniform1i(program.uniform("crack_cells"), kUnit);
  glUniform1i(program.uniform("crack_table"), kTableUnit);
  glUniform1i(program.uniform("crack_on"), on ? 1 : 0);
  if (!on) return;
  const render::CrackTableData& table = table_data_;
  cells_.bind(kUnit);
  glUniform1fv(program.uniform("crack_ground"), palette.nodes(), palette.ground());
  table_.bind(kTableUnit);
  glUniform1i(program.uniform("crack_corrected"),
              settings.crack_model == render::CrackModel::Corrected ? 1 : 0);
  glUniform1i(program.uniform("crack_table_rows"), table.ratio_count);
  glUniform1i(program.uniform("crack_table_rho0s"), table.rho0_count);
  glUniform1f(program.uniform("crack_table_stride"), kTableStride);
  glUniform1fv(program.uniform("crack_table_last_F"), paintcore::kCrackShapeCount,
               table.last_F.data());
  glUniform1fv(program.uniform("crack_table_last_G"), paintcore::kCrackShapeCount,
               table.last_G.data());
}

void CrackTexture::bind_close_up(const ShaderProgram& program,
                                 const render::RenderSettings& settings, float min_pixels) {
  const bool on = settings.cracks && cells_.id() != 0 && min_pixels > 0.0f;
  glUniform1i(program.uniform("crack_shapes"), kShapeUnit);
  glUniform1i(program.uniform("close_up_on"), on ? 1 : 0);
  if (!on) return;
  shapes_.bind(kShapeUnit);
  glUniform1f(program.uniform("close_up_min_pixels"), min_pixels);
  // The CPU close-up's light (render_painting_close_up): the disc's directions, and the
  // irradiances of sky and sun as shares of the canvas's.
  const render::CloseUpLight light = render::close_up_light(settings);
  std::vector<float> suns, swapped;
  for (const render::CanvasVec& s : render::close_up_light_directions(light)) {
    suns.insert(suns.end(),
                {static_cast<float>(s.x), static_cast<float>(s.y), static_cast<float>(s.z)});
    swapped.insert(swapped.end(),
                   {static_cast<float>(s.y), static_cast<float>(s.x), static_cast<float>(s.z)});
  }
  const int rays = static_cast<int>(suns.size() / 3);
  glUniform3fv(program.uniform("close_up_suns"), rays, suns.data());
  glUniform3fv(program.uniform("close_up_suns_swapped"), rays, swapped.data());
  glUniform1i(program.uniform("close_up_rays"), rays);
  const render::CloseUpIrradiance irradiance = render::close_up_irradiance(light);
  glUniform1f(program.uniform("close_up_e_sky"), static_cast<float>(irradiance.sky));
  glUniform1f(program.uniform("close_up_e_sun"), static_cast<float>(irradiance.sun));
  // GLSL's mat3 is column-major; the row-major matrices go in transposed.
  const std::array<double, 9> m = render::xyz_to_linear_srgb();
  const std::array<double, 9> inverse = render::invert_3x3(m);
  std::array<float, 9> to_rgb{}, to_xyz{};
  for (int i = 0; i < 9; ++i) {
    to_rgb[static_cast<std::size_t>(i)] = static_cast<float>(m[static_cast<std::size_t>(i)]);
    to_xyz[static_cast<std::size_t>(i)] = static_cast<float>(inverse[static_cast<std::size_t>(i)]);
  }
  glUniformMatrix3fv(program.uniform("xyz_to_linear_rgb"), 1, GL_TRUE, to_rgb.data());
  glUniformMatrix3fv(program.uniform("linear_rgb_to_xyz"), 1, GL_TRUE, to_xyz.data());
}

}  // namespace impasto::render_gl
