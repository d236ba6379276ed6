#pragma once
// The ghs surface model on the GPU: what render/gl/shaders/surface_ghs_lib.glsl reads, made by
// the CPU reference's own code (render::SurfaceShading and its surface::GhsBrdf tables), so
// that both sides shade from the same numbers. For the blinn model it holds nothing and
// switches the shader's ghs branch off.
//
// Surfaces are blocks (rows of the tables texture, one layer a node): the settings' dry
// surface, the wet one, then every level of paint and of varnish that SurfaceShading
// quantises a painting's own media and varnish to (filled when a cell first needs one). A
// per-cell texture says which block each cell's dry surface is and the least wetness it
// has (a varnish not yet dry); it is made only when a tile first holds media or varnish.
#include <memory>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render/surface_brdf.hpp"
#include "impasto/render/surface_shading.hpp"
#include "impasto/render_gl/shader_program.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class GhsSurfaceTables {
 public:
  static constexpr int kTableSize = render::surface::GhsBrdf::kTableSize;
  // A block's row: kTableSize texels (renormalisation, directional albedo) at cos θ =
  // i / (kTableSize − 1), then (index, hemispherical albedo), then (RMS, correlation) µm,
  // then kTableSize texels (shadowing, multiply scattered lobe's factor) at the same cosines.
  static constexpr int kColumns = 2 * kTableSize + 2;
  static constexpr int kSecondTable = kTableSize + 2;
  static constexpr int kDryBlock = 0, kWetBlock = 1;
  static constexpr int kBlocks = 2 + 2 * render::SurfaceShading::kLevels;
  static constexpr int kTablesUnit = 10, kCellsUnit = 9;  // texture units (below the cracks')

  GhsSurfaceTables(int width_cells, int height_cells, const render::RenderSettings& settings,
                   const render::SpectralPalette& palette);

  bool active() const { return shading_ != nullptr; }
  // A new light elevation or disc: the tables of every block in use made again; the cells
  // keep their blocks.
  void set_light(const render::RenderSettings& settings, const render::SpectralPalette& palette);
  // The cells' surfaces of one tile (nothing while no tile has held media or varnish).
  void upload_tile(const paintcore::Canvas& canvas, int tile_index);

  // Sets the ghs uniforms and binds the textures (ghs_enabled false when inactive).
  void bind(const ShaderProgram& program) const;

  // The block of a cell's dry surface (SurfaceShading::cell_dry).
  static int block_of(const render::SurfaceShading::CellDry& dry);

 private:
  void make(const render::RenderSettings& settings, const render::SpectralPalette& palette);
  void fill_block(int block);

  int width_, height_;
  int nodes_ = 0;
  std::unique_ptr<render::SurfaceShading> shading_;
  Texture tables_;  // kColumns x kBlocks x MAX_NODES layers, RG32F
  std::vector<bool> filled_;
  Texture cells_;  // (block, least wetness) per cell, RG32F; made with the first surface tile
  bool cells_made_ = false;
  std::vector<float> scratch_;
  std::vector<float> wavelength_nm_;  // MAX_NODES
  std::vector<float> reference_;      // 2 per node (direct, sky)
  float source_sigma_ = 0.0f, subcell_slope_ = 0.0f;
  bool reflection_ = true;
};

// The surface_ghs_lib.glsl source with GHS_TABLE_SIZE, GHS_BLOCKS and GHS_WET_BLOCK #defined
// from the C++ above (needs MAX_NODES and shading_glsl before it).
const char* surface_ghs_glsl();

}  // namespace impasto::render_gl
