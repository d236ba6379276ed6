#pragma once
// The ghs surface model on the GPU: what render/gl/shaders/surface_ghs_lib.glsl reads, made by
// the CPU reference's own code (render::SurfaceShading and its surface::GhsBrdf tables), so
// that both sides shade from the same numbers. For the blinn model it holds nothing and
// switches the shader's ghs branch off.
#include <memory>
#include <string>
#include <vector>

#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render/surface_brdf.hpp"
#include "impasto/render/surface_shading.hpp"
#include "impasto/render_gl/shader_program.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class GhsSurfaceTables {
 public:
  // Rows of surfaces per node: the dry one (the medium's, or the varnish's), then the wet.
  // A medium stored per mix would add rows here and a texture choosing between them.
  static constexpr int kSurfaces = 2;
  static constexpr int kTableSize = render::surface::GhsBrdf::kTableSize;
  static constexpr int kUnit = 10;  // texture unit of the tables (below the crack units)

  GhsSurfaceTables(const render::RenderSettings& settings, const render::SpectralPalette& palette);

  bool active() const { return shading_ != nullptr; }

  // Sets the ghs uniforms and binds the tables (ghs_enabled false when inactive).
  void bind(const ShaderProgram& program) const;

 private:
  std::unique_ptr<render::SurfaceShading> shading_;
  Texture tables_;  // kTableSize x kSurfaces * MAX_NODES, RG32F: renormalisation, albedo
  std::vector<float> roughness_;      // 2 per surface
  std::vector<float> index_;          // kSurfaces * MAX_NODES
  std::vector<float> hemispherical_;  // kSurfaces * MAX_NODES
  std::vector<float> wavelength_nm_;  // MAX_NODES
  std::vector<float> reference_;      // 2 per node (direct, sky)
  float source_sigma_ = 0.0f, subcell_slope_ = 0.0f;
  bool reflection_ = true;
};

// The surface_ghs_lib.glsl source with GHS_TABLE_SIZE and GHS_SURFACES #defined from the C++
// above (needs MAX_NODES and shading_glsl before it).
const char* surface_ghs_glsl();

}  // namespace impasto::render_gl
