#include "impasto/render_gl/crack_texture.hpp"

#include <algorithm>

#include "impasto/render/crack_shading.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;
using paintcore::kTileSize;

void CrackTexture::upload_tile(const paintcore::Canvas& canvas, int tile_index) {
  const paintcore::CrackTile* tile = canvas.cracks().tile(tile_index);
  if (tile == nullptr && cells_.id() == 0) return;  // no crack anywhere yet
  if (cells_.id() == 0) {
    cells_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
    const std::vector<float> zeros(4 * static_cast<std::size_t>(width_) * height_, 0.0f);
    cells_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
    const render::CrackTableData& table = render::crack_table_data();
    const int rows = table.ratio_count * static_cast<int>(table.last_F.size());
    table_ = Texture(table.rho0_count, rows, 0, TexelFormat::kR32F);
    table_.upload(0, 0, table.rho0_count, rows, 0, table.differences.data(), table.rho0_count);
  }
  const int x0 = (tile_index % canvas.tiles_x()) * kTileSize;
  const int y0 = (tile_index / canvas.tiles_x()) * kTileSize;
  const int w = std::min(kTileSize, width_ - x0);
  const int h = std::min(kTileSize, height_ - y0);
  scratch_.assign(4 * static_cast<std::size_t>(kTileCells), 0.0f);
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
  }
  cells_.upload(x0, y0, w, h, 0, scratch_.data(), kTileSize);
}

void CrackTexture::bind(const ShaderProgram& program, const render::SpectralPalette& palette,
                        bool enabled) const {
  const bool on = enabled && cells_.id() != 0;
  glUniform1i(program.uniform("crack_cells"), kUnit);
  glUniform1i(program.uniform("crack_table"), kTableUnit);
  glUniform1i(program.uniform("crack_on"), on ? 1 : 0);
  if (!on) return;
  cells_.bind(kUnit);
  glUniform1fv(program.uniform("crack_ground"), palette.nodes(), palette.ground());
  const render::CrackTableData& table = render::crack_table_data();
  table_.bind(kTableUnit);
  glUniform1i(program.uniform("crack_corrected"), render::kCrackTableCorrection ? 1 : 0);
  glUniform1i(program.uniform("crack_table_rows"), table.ratio_count);
  glUniform1i(program.uniform("crack_table_rho0s"), table.rho0_count);
  glUniform1f(program.uniform("crack_table_stride"), kTableStride);
  glUniform1fv(program.uniform("crack_table_last_F"), 6, table.last_F.data());
  glUniform1fv(program.uniform("crack_table_last_G"), 6, table.last_G.data());
}

}  // namespace impasto::render_gl
