#pragma once
// Cracks on the GPU: what render/gl/shaders/cracks_lib.glsl reads. Per cell the far-view
// optics of its crack (render::crack_optics: coverage, Gouffe's F and G, and in the fourth
// channel sign(walls are the ground) (1 + shape kTableStride + table_u + 1)) in an RGBA32F
// texture, updated tile by tile; the ground reflectance per node as a uniform; and the
// cavity correction for the light (render::crack_table_data) as an R32F texture. Like the CPU hook
// it costs nothing where there are no cracks: the texture is made only when a tile first holds a
// crack, and until then the shader skips it.
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render_gl/shader_program.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class CrackTexture {
 public:
  static constexpr int kUnit = 13;              // texture unit of the crack sampler
  static constexpr int kTableUnit = 12;         // texture unit of the correction table
  static constexpr int kShapeUnit = 11;         // texture unit of the cavities' sizes
  static constexpr float kTableStride = 64.0f;  // > ratio_count + 1: packs shape and L/R

  CrackTexture(int width_cells, int height_cells) : width_(width_cells), height_(height_cells) {}

  // The crack optics of one tile (nothing while no tile has held a crack).
  void upload_tile(const paintcore::Canvas& canvas, int tile_index);
  // Uploads the correction for the settings' light when it changed; call before binding
  // anything for the draw (an upload binds the texture to the active unit).
  void prepare(const render::RenderSettings& settings);
  // Sets crack_on (false without a texture or when settings.cracks is false), binds the
  // textures and sets the ground reflectance per node and the cavity model's uniforms.
  void bind(const ShaderProgram& program, const render::SpectralPalette& palette,
            const render::RenderSettings& settings) const;
  // The close-up's uniforms (crack_close_up_canvas_lib.glsl): on from `min_pixels` pixels per
  // cell (0: off), the light's disc, and the colour matrices.
  void bind_close_up(const ShaderProgram& program, const render::RenderSettings& settings,
                     float min_pixels);

 private:
  int width_, height_;
  Texture cells_;   // allocated with the first tile holding a crack
  Texture shapes_;  // per cell: depth, half-width (mm), bare canvas normal x, y (close-up)
  Texture table_;   // the correction for the light (render::crack_table_data)
  render::CrackTableData table_data_;  // what table_ holds
  std::vector<float> scratch_, shape_scratch_;
};

}  // namespace impasto::render_gl
