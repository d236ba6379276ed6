#include "impasto/render_gl/ghs_surface_tables.hpp"

#include <string>

#include "embedded_shaders.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render_gl {

// The shader interpolates between entries k and k + 1 (ghs_table), and the table texture's
// rows (a surface and a node each) stay far inside GL 3.3's smallest texture size (1024).
static_assert(GhsSurfaceTables::kTableSize >= 2);
static_assert(GhsSurfaceTables::kSurfaces * render::kMaxNodes <= 1024);
// The last row block is the wet surface (GHS_WET in the shader), the first the dry one.
static_assert(GhsSurfaceTables::kSurfaces == 2);

GhsSurfaceTables::GhsSurfaceTables(const render::RenderSettings& settings,
                                   const render::SpectralPalette& palette)
    : shading_(render::SurfaceShading::create(settings, palette)),
      tables_(kTableSize, kSurfaces * render::kMaxNodes, 0, TexelFormat::kRG32F) {
  if (!shading_) return;
  const int nodes = palette.nodes();
  const auto rows = static_cast<std::size_t>(kSurfaces * render::kMaxNodes);
  std::vector<float> texels(rows * kTableSize * 2, 0.0f);
  index_.assign(rows, 1.0f);
  hemispherical_.assign(rows, 0.0f);
  roughness_.assign(2 * kSurfaces, 0.0f);
  wavelength_nm_.assign(render::kMaxNodes, 550.0f);
  reference_.assign(2 * render::kMaxNodes, 1.0f);
  for (int node = 0; node < nodes; ++node) {
    for (int s = 0; s < kSurfaces; ++s) {
      const render::surface::GhsBrdf& brdf =
          s == 0 ? shading_->dry_brdf(node) : shading_->wet_brdf(node);
      const auto row = static_cast<std::size_t>(s * render::kMaxNodes + node);
      // The tables at their own points: k / (size − 1) interpolates to entry k exactly.
      for (int k = 0; k < kTableSize; ++k) {
        const double mu = static_cast<double>(k) / (kTableSize - 1);
        float* texel = &texels[2 * (row * kTableSize + static_cast<std::size_t>(k))];
        texel[0] = static_cast<float>(brdf.renormalisation(mu));
        texel[1] = static_cast<float>(brdf.albedo(mu));
      }
      index_[row] = static_cast<float>(brdf.params().index);
      hemispherical_[row] = static_cast<float>(brdf.hemispherical_albedo());
      // Every node of a surface has the same roughness, source and slopes.
      roughness_[2 * static_cast<std::size_t>(s)] =
          static_cast<float>(brdf.params().roughness.rms_um);
      roughness_[2 * static_cast<std::size_t>(s) + 1] =
          static_cast<float>(brdf.params().roughness.correlation_um);
      source_sigma_ = static_cast<float>(brdf.params().source_sigma);
      subcell_slope_ = static_cast<float>(brdf.params().subcell_slope_rms);
    }
    const auto k = static_cast<std::size_t>(node);
    wavelength_nm_[k] = static_cast<float>(palette.sampling().wavelengths_nm[k]);
    reference_[2 * k] = shading_->reference(node);
    reference_[2 * k + 1] = shading_->reference_sky(node);
  }
  reflection_ = shading_->reflection();
  tables_.upload(0, 0, kTableSize, kSurfaces * render::kMaxNodes, 0, texels.data(), kTableSize);
}

void GhsSurfaceTables::bind(const ShaderProgram& program) const {
  glUniform1i(program.uniform("ghs_enabled"), active() ? 1 : 0);
  glUniform1i(program.uniform("ghs_tables"), kUnit);
  tables_.bind(kUnit);
  if (!active()) return;
  glUniform1i(program.uniform("ghs_reflection"), reflection_ ? 1 : 0);
  glUniform2fv(program.uniform("ghs_roughness"), kSurfaces, roughness_.data());
  glUniform1fv(program.uniform("ghs_index"), static_cast<GLsizei>(index_.size()), index_.data());
  glUniform1fv(program.uniform("ghs_hemispherical"), static_cast<GLsizei>(hemispherical_.size()),
               hemispherical_.data());
  glUniform1fv(program.uniform("ghs_wavelength_nm"), render::kMaxNodes, wavelength_nm_.data());
  glUniform2fv(program.uniform("ghs_reference"), render::kMaxNodes, reference_.data());
  glUniform1f(program.uniform("ghs_source_sigma"), source_sigma_);
  glUniform1f(program.uniform("ghs_subcell_slope"), subcell_slope_);
}

const char* surface_ghs_glsl() {
  static const std::string source =
      "#define GHS_TABLE_SIZE " + std::to_string(GhsSurfaceTables::kTableSize) +
      "\n#define GHS_SURFACES " + std::to_string(GhsSurfaceTables::kSurfaces) + "\n" +
      shaders::surface_ghs_lib;
  return source.c_str();
}

}  // namespace impasto::render_gl
