#pragma once
// Flake paint on the GPU: what render/gl/shaders/flakes_lib.glsl reads. The tables of each
// flake pigment (P, ⟨s⟩, ⟨t_p⟩, r_p per node) in one R32F texture, the top paint layer of
// every cell (thickness and flake concentrations) in an RGBA32F texture, and the light as
// uniforms. Like the CPU hook (render::FlakeShading) it costs nothing where it is absent: no
// textures at all when no pigment of the palette has flakes, and the per-cell texture is
// made only when a tile first holds flake paint.
#include <memory>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/flake_shading.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render_gl/shader_program.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class FlakeTextures {
 public:
  static constexpr int kMaxFlakePigments = 3;  // MAX_FLAKES in flakes_lib.glsl (flakes_glsl)
  // The texture units the flake samplers use (above the canvas pass's own).
  static constexpr int kLayerUnit = 14, kTablesUnit = 15;

  // Throws std::runtime_error when the palette has more than kMaxFlakePigments flake
  // pigments or a flake file is bad.
  FlakeTextures(int width_cells, int height_cells, const render::RenderSettings& settings,
                const render::SpectralPalette& palette);

  bool active() const { return shading_ != nullptr; }

  // The top-layer texture for one tile (nothing while no tile has held flake paint).
  void upload_tile(const paintcore::Canvas& canvas, int tile_index);

  // Sets the flake uniforms and binds the textures (flake_count 0 when inactive). The light's
  // direction comes from `settings` (it may have moved since construction); its kind and
  // size are those the textures were made for.
  void bind(const ShaderProgram& program, const render::RenderSettings& settings,
            double cell_mm) const;

 private:
  int width_, height_;
  std::unique_ptr<render::FlakeShading> shading_;
  std::vector<float> node_to_xyz_;  // 3 per node
  Texture tables_;
  Texture layer_;  // allocated with the first tile holding flake paint
  std::vector<float> scratch_;
};

}  // namespace impasto::render_gl
