#pragma once
// Cracks on the GPU: what render/gl/shaders/cracks_lib.glsl reads. Per cell the far-view
// optics of its crack (render::crack_optics: coverage, Gouffe's F and G, and in the fourth
// channel sign(walls are the ground) (1 + shape kTableStride + table_u + 1)) in an RGBA32F
// texture, updated tile by tile; the ground reflectance per node as a uniform; and the
// cavity correction table (cracks::CavityTable::differences) as an R32F texture. Like the CPU hook
// it costs nothing where there are no cracks: the texture is made only when a tile first holds a
// crack, and until then the shader skips it.
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render_gl/shader_program.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class CrackTexture {
 public:
  static constexpr int kUnit = 13;              // texture unit of the crack sampler
  static constexpr int kTableUnit = 12;         // texture unit of the correction table
  static constexpr float kTableStride = 64.0f;  // > ratio_count + 1: packs shape and L/R

  CrackTexture(int width_cells, int height_cells) : width_(width_cells), height_(height_cells) {}

  // The crack optics of one tile (nothing while no tile has held a crack).
  void upload_tile(const paintcore::Canvas& canvas, int tile_index);
  // Sets crack_on (false without a texture or when `enabled` is false), binds the texture and
  // sets the ground reflectance per node.
  void bind(const ShaderProgram& program, const render::SpectralPalette& palette,
            bool enabled) const;

 private:
  int width_, height_;
  Texture cells_;  // allocated with the first tile holding a crack
  Texture table_;  // the correction table (render::crack_table_data), uploaded with cells_
  std::vector<float> scratch_;
};

}  // namespace impasto::render_gl
