#include "impasto/render_gl/ghs_surface_tables.hpp"

#include <algorithm>
#include <string>

#include "embedded_shaders.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render_gl {

// The shader interpolates between entries k and k + 1 (ghs_table); the blocks are rows and
// the nodes layers of one array texture, inside GL 3.3's smallest limits (1024 and 256).
static_assert(GhsSurfaceTables::kTableSize >= 2);
static_assert(GhsSurfaceTables::kBlocks <= 1024 && GhsSurfaceTables::kColumns <= 1024);
static_assert(render::kMaxNodes <= 256);
static_assert(GhsSurfaceTables::kDryBlock == 0);  // an empty cell texel (0, 0) is the settings'

GhsSurfaceTables::GhsSurfaceTables(int width_cells, int height_cells,
                                   const render::RenderSettings& settings,
                                   const render::SpectralPalette& palette)
    : width_(width_cells),
      height_(height_cells),
      tables_(kColumns, kBlocks, render::kMaxNodes, TexelFormat::kRG32F),
      cells_(1, 1, 0, TexelFormat::kRG32F) {
  make(settings, palette);
}

void GhsSurfaceTables::make(const render::RenderSettings& settings,
                            const render::SpectralPalette& palette) {
  shading_ = render::SurfaceShading::create(settings, palette);
  if (!shading_) return;
  nodes_ = palette.nodes();
  wavelength_nm_.assign(render::kMaxNodes, 550.0f);
  reference_.assign(2 * render::kMaxNodes, 1.0f);
  for (int node = 0; node < nodes_; ++node) {
    const auto k = static_cast<std::size_t>(node);
    wavelength_nm_[k] = static_cast<float>(palette.sampling().wavelengths_nm[k]);
    reference_[2 * k] = shading_->reference(node);
    reference_[2 * k + 1] = shading_->reference_sky(node);
  }
  // Every surface of a renderer has the same light disc and sub-cell slopes.
  source_sigma_ = static_cast<float>(shading_->dry_brdf(0).params().source_sigma);
  subcell_slope_ = static_cast<float>(shading_->dry_brdf(0).params().subcell_slope_rms);
  reflection_ = shading_->reflection();
  filled_.resize(kBlocks, false);
  filled_[kDryBlock] = filled_[kWetBlock] = true;
  for (int block = 0; block < kBlocks; ++block) {
    if (filled_[static_cast<std::size_t>(block)]) fill_block(block);
  }
}

void GhsSurfaceTables::set_light(const render::RenderSettings& settings,
                                 const render::SpectralPalette& palette) {
  make(settings, palette);
}

int GhsSurfaceTables::block_of(const render::SurfaceShading::CellDry& dry) {
  if (dry.level < 0) return kDryBlock;
  return 2 + (dry.varnish ? render::SurfaceShading::kLevels : 0) + dry.level;
}

void GhsSurfaceTables::fill_block(int block) {
  constexpr int kLevels = render::SurfaceShading::kLevels;
  const render::SurfaceShading::Brdfs* level = nullptr;
  if (block >= 2) level = &shading_->level_brdfs(block >= 2 + kLevels, (block - 2) % kLevels);
  std::vector<float> row(2 * kColumns);
  for (int node = 0; node < nodes_; ++node) {
    const render::surface::GhsBrdf& brdf = block == kDryBlock ? shading_->dry_brdf(node)
                                           : block == kWetBlock
                                               ? shading_->wet_brdf(node)
                                               : *(*level)[static_cast<std::size_t>(node)];
    // The tables at their own points: k / (size − 1) interpolates to entry k exactly.
    for (int k = 0; k < kTableSize; ++k) {
      const double mu = static_cast<double>(k) / (kTableSize - 1);
      row[static_cast<std::size_t>(2 * k)] = static_cast<float>(brdf.renormalisation(mu));
      row[static_cast<std::size_t>(2 * k + 1)] = static_cast<float>(brdf.albedo(mu));
      row[static_cast<std::size_t>(2 * (kSecondTable + k))] =
          static_cast<float>(brdf.shadowing(mu));
      row[static_cast<std::size_t>(2 * (kSecondTable + k) + 1)] =
          static_cast<float>(brdf.multiple(mu));
    }
    row[2 * kTableSize] = static_cast<float>(brdf.params().index);
    row[2 * kTableSize + 1] = static_cast<float>(brdf.hemispherical_albedo());
    row[2 * kTableSize + 2] = static_cast<float>(brdf.params().roughness.rms_um);
    row[2 * kTableSize + 3] = static_cast<float>(brdf.params().roughness.correlation_um);
    tables_.upload(0, block, kColumns, 1, node, row.data(), kColumns);
  }
  filled_[static_cast<std::size_t>(block)] = true;
}

void GhsSurfaceTables::upload_tile(const paintcore::Canvas& canvas, int tile_index) {
  if (!active()) return;
  const paintcore::Tile* tile = canvas.tile(tile_index);
  const bool has = paintcore::has_surface(tile);
  if (!has && !cells_made_) return;
  if (!cells_made_) {
    cells_made_ = true;
    cells_ = Texture(width_, height_, 0, TexelFormat::kRG32F);
    std::vector<float> zeros(2 * static_cast<std::size_t>(width_), 0.0f);
    for (int y = 0; y < height_; ++y) cells_.upload(0, y, width_, 1, 0, zeros.data(), width_);
  }
  using paintcore::kTileCells;
  using paintcore::kTileSize;
  const int x0 = (tile_index % canvas.tiles_x()) * kTileSize;
  const int y0 = (tile_index / canvas.tiles_x()) * kTileSize;
  const int w = std::min(kTileSize, width_ - x0), h = std::min(kTileSize, height_ - y0);
  scratch_.assign(2 * static_cast<std::size_t>(kTileCells), 0.0f);
  if (has) {
    for (int cell = 0; cell < kTileCells; ++cell) {
      const render::SurfaceShading::CellDry dry =
          shading_->cell_dry(paintcore::cell_surface(tile, cell));
      const int block = block_of(dry);
      if (!filled_[static_cast<std::size_t>(block)]) fill_block(block);
      scratch_[2 * static_cast<std::size_t>(cell)] = static_cast<float>(block);
      scratch_[2 * static_cast<std::size_t>(cell) + 1] = dry.min_wetness;
    }
  }
  cells_.upload(x0, y0, w, h, 0, scratch_.data(), kTileSize);
}

void GhsSurfaceTables::bind(const ShaderProgram& program) const {
  glUniform1i(program.uniform("ghs_enabled"), active() ? 1 : 0);
  glUniform1i(program.uniform("ghs_tables"), kTablesUnit);
  glUniform1i(program.uniform("ghs_cells"), kCellsUnit);
  tables_.bind(kTablesUnit);
  cells_.bind(kCellsUnit);
  if (!active()) return;
  glUniform1i(program.uniform("ghs_cells_present"), cells_made_ ? 1 : 0);
  glUniform1i(program.uniform("ghs_reflection"), reflection_ ? 1 : 0);
  glUniform1fv(program.uniform("ghs_wavelength_nm"), render::kMaxNodes, wavelength_nm_.data());
  glUniform2fv(program.uniform("ghs_reference"), render::kMaxNodes, reference_.data());
  glUniform1f(program.uniform("ghs_source_sigma"), source_sigma_);
  glUniform1f(program.uniform("ghs_subcell_slope"), subcell_slope_);
}

const char* surface_ghs_glsl() {
  static const std::string source =
      "#define GHS_TABLE_SIZE " + std::to_string(GhsSurfaceTables::kTableSize) +
      "\n#define GHS_BLOCKS " + std::to_string(GhsSurfaceTables::kBlocks) +
      "\n#define GHS_WET_BLOCK " + std::to_string(GhsSurfaceTables::kWetBlock) +
      "\n#define GHS_SECOND_TABLE " + std::to_string(GhsSurfaceTables::kSecondTable) + "\n" +
      shaders::optics_lib + shaders::surface_ghs_lib;
  return source.c_str();
}

}  // namespace impasto::render_gl
