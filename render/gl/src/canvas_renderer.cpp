#include "impasto/render_gl/canvas_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "embedded_shaders.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render/shading_key.hpp"
#include "impasto/render/subsurface.hpp"
#include "impasto/render_gl/dry_reflectance.hpp"
#include "impasto/render_gl/ghs_surface_tables.hpp"
#include "impasto/render_gl/shader_library.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

paintcore::CellRect grown(const paintcore::CellRect& r, int by) {
  return {r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by};
}

paintcore::CellRect united(const paintcore::CellRect& a, const paintcore::CellRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

paintcore::CellRect intersected(const paintcore::CellRect& a, const paintcore::CellRect& b) {
  const paintcore::CellRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                              std::min(a.y1, b.y1)};
  return r.empty() ? paintcore::CellRect{} : r;
}

// Whether any dry layer has paint in the tile (hidden or not: a hidden layer's tile keeps its
// place, which a shown one will need).
bool has_dry_paint(const paintcore::Canvas& canvas, int tile_index) {
  return std::any_of(canvas.dry_layers().begin(), canvas.dry_layers().end(),
                     [&](const paintcore::DryLayer& layer) { return layer.find(tile_index); });
}

int layers_for(int count) {
  return std::max(1, (count + 3) / 4);
}

void check_palette(const render::SpectralPalette& palette) {
  if (palette.nodes() < 1 || palette.nodes() > render::kMaxNodes) {
    throw std::runtime_error("GPU renderer: " + std::to_string(palette.nodes()) +
                             " wavelength nodes; the shaders take 1.." +
                             std::to_string(render::kMaxNodes) +
                             " (full-spectrum rendering is CPU only)");
  }
  if (palette.pigment_count() > paintcore::kMaxPigmentSlots) {
    throw std::runtime_error("GPU renderer: more than " +
                             std::to_string(paintcore::kMaxPigmentSlots) + " pigments");
  }
}

}  // namespace

// Staging memory for one tile, interleaved the way the textures store it.
struct CanvasRenderer::TileScratch {
  std::vector<float> pigments;            // [layer][cell][4]
  std::vector<float> surface;             // [cell][2]
  std::array<float, kTileCells> weave{};  // a bare tile's heights (mm)
  std::vector<float> dry_node_major;      // [node][cell]
  std::vector<float> dry_interleaved;     // [layer][cell][4]
};

CanvasRenderer::CanvasRenderer(int width_cells, int height_cells,
                               const render::RenderSettings& settings,
                               render::SpectralPalette palette, GpuViewOptions options)
    : width_(width_cells),
      height_(height_cells),
      settings_(settings),
      palette_(std::move(palette)),
      options_(options) {
  render::validate(settings_);
  check_palette(palette_);
  surface_ = Texture(width_, height_, 0, TexelFormat::kRG32F);
  allocate_textures();
  bare_reflectance_ = bare_ground_reflectance(settings_, palette_);
  build_program();
  flakes_ = std::make_unique<FlakeTextures>(width_, height_, settings_, palette_);
  cracks_ = std::make_unique<CrackTexture>(width_, height_);
  ghs_ = std::make_unique<GhsSurfaceTables>(width_, height_, settings_, palette_);
  spread_ = std::make_unique<GpuSubsurfaceSpread>(width_, height_);
}

CanvasRenderer::~CanvasRenderer() = default;

void CanvasRenderer::allocate_textures() {
  const int pigment_layers = layers_for(palette_.pigment_count());
  const int node_layers = layers_for(palette_.nodes());
  if (pigment_layers == pigment_layers_ && node_layers == node_layers_) return;
  pigment_layers_ = pigment_layers;
  node_layers_ = node_layers;
  tile_data_ = TileAtlas((width_ + kTileSize - 1) / kTileSize,
                         (height_ + kTileSize - 1) / kTileSize, pigment_layers_ + node_layers_);
  dry_bakes_.clear();
}

void CanvasRenderer::build_program() {
  if (!display_ || display_->encoding() != settings_.display) {
    display_ = std::make_unique<GpuDisplayTransform>(settings_.display);
  }
  std::string source = "#version 330 core\n#define MAX_NODES " + std::to_string(render::kMaxNodes) +
                       "\n#define MAX_SLOTS " + std::to_string(paintcore::kMaxPigmentSlots) +
                       "\n#define TILE_SIZE " + std::to_string(kTileSize) + "\n";
  source += shaders::km_lib;
  source += shading_glsl();
  source += surface_ghs_glsl();
  source += relief_glsl();
  source += flakes_glsl();
  source += cracks_glsl();
  source += shaders::crack_close_up_lib;
  source += shaders::crack_close_up_canvas_lib;
  source += display_->glsl();
  source += GpuSubsurfaceSpread::canvas_glsl();
  source += shaders::tile_atlas_lib;
  source += shaders::canvas_km_frag;
  pass_ = std::make_unique<FullscreenPass>("canvas_km_frag.glsl", std::move(source));
}

void CanvasRenderer::set_settings(const render::RenderSettings& settings,
                                  render::SpectralPalette palette) {
  render::validate(settings);
  check_palette(palette);
  const bool encoding_changed = settings.display != settings_.display;
  settings_ = settings;
  palette_ = std::move(palette);
  dry_bakes_.clear();  // the reflectance follows the light, pigments and settings
  allocate_textures();
  bare_reflectance_ = bare_ground_reflectance(settings_, palette_);
  if (encoding_changed) build_program();
  flakes_ = std::make_unique<FlakeTextures>(width_, height_, settings_, palette_);
  ghs_ = std::make_unique<GhsSurfaceTables>(width_, height_, settings_, palette_);
  spread_->clear();  // the map and kernels come with upload_all
  spread_stale_ = spread_written_;
}

void CanvasRenderer::set_view_options(const GpuViewOptions& options) {
  // The body's light scales with the exposure: the spread's change with it.
  if (options.light_intensity != options_.light_intensity) spread_stale_ = spread_written_;
  options_ = options;
}

bool CanvasRenderer::spread_on() const {
  return settings_.surface.model == render::SurfaceModel::ghs && settings_.surface.subsurface;
}

void CanvasRenderer::set_shading(const render::RenderSettings& settings) {
  // The ghs tables depend on the light's elevation (the body's reference) and its disc.
  const bool ghs_light_changed =
      ghs_->active() && (settings.light_elevation_deg != settings_.light_elevation_deg ||
                         settings.shadow_light_diameter_deg != settings_.shadow_light_diameter_deg);
  // The shading and the shader's colour uniforms (Saunderson; the crack correction, which
  // follows the light in draw()), listed once in render/shading_key.hpp.
  render::copy_shading_settings(settings, settings_);
  render::validate(settings_);
  if (ghs_light_changed) ghs_->set_light(settings_, palette_);     // the cells keep their surfaces
  spread_stale_ = united(spread_written_, spread_->mapped_box());  // the body's light changed
}

render::relief::Reach CanvasRenderer::relief_reach() const {
  render::relief::Reach reach =
      render::relief::reach(render::relief::relief_params(settings_, cell_mm_, height_range_));
  // A cell's light spreads up to the radius: a change reaches that much further.
  if (spread_on()) {
    for (int* side : {&reach.left, &reach.top, &reach.right, &reach.bottom}) {
      *side += spread_->radius();
    }
  }
  return reach;
}

void CanvasRenderer::upload_tile(const paintcore::Canvas& canvas, int tile_index,
                                 TileScratch& scratch) {
  const int tx = tile_index % canvas.tiles_x();
  const int ty = tile_index / canvas.tiles_x();
  const int x0 = tx * kTileSize, y0 = ty * kTileSize;
  const int w = std::min(kTileSize, width_ - x0);
  const int h = std::min(kTileSize, height_ - y0);
  const paintcore::Tile* tile = canvas.tile(tile_index);
  const render::VisibleDryStack dry =
      render::visible_dry_stack(canvas, tile_index, palette_, hidden_dry_layers_);
  // Paint or dry layers take a place in the atlas (and keep it); a bare tile shows the weave.
  if (tile != nullptr || !dry.layers.empty()) tile_data_.place(tile_index);

  scratch.surface.assign(2 * kTileCells, 0.0f);
  if (tile == nullptr) canvas.compute_base_heights(tile_index, scratch.weave.data());
  float lowest = std::numeric_limits<float>::max();
  float highest = std::numeric_limits<float>::lowest();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int cell = y * kTileSize + x;
      if (tile != nullptr) {
        scratch.surface[2 * cell] = tile->wet_volume_mm[cell];
        scratch.surface[2 * cell + 1] = paintcore::surface_height_mm(*tile, cell);
      } else {
        scratch.surface[2 * cell + 1] = scratch.weave[static_cast<std::size_t>(cell)];
      }
      lowest = std::min(lowest, scratch.surface[2 * cell + 1]);
      highest = std::max(highest, scratch.surface[2 * cell + 1]);
    }
  }
  tile_min_height_.resize(static_cast<std::size_t>(canvas.tile_count()), 0.0f);
  tile_max_height_.resize(static_cast<std::size_t>(canvas.tile_count()), 0.0f);
  dry_bakes_.resize(static_cast<std::size_t>(canvas.tile_count()));
  tile_min_height_[static_cast<std::size_t>(tile_index)] = lowest;
  tile_max_height_[static_cast<std::size_t>(tile_index)] = highest;
  surface_.upload(x0, y0, w, h, 0, scratch.surface.data(), kTileSize);
  if (tile_data_.placed(tile_index)) upload_tile_data(tile, dry, tile_index, w, h, scratch);
  flakes_->upload_tile(canvas, tile_index);
  cracks_->upload_tile(canvas, tile_index);
  ghs_->upload_tile(canvas, tile_index);
  if (spread_on()) {
    const paintcore::CellRect cells{x0, y0, x0 + w, y0 + h};
    spread_->set_cells(cells, render::subsurface_map(canvas, palette_, settings_, cells));
    spread_stale_ = united(spread_stale_, cells);
  }
}

void CanvasRenderer::upload_tile_data(const paintcore::Tile* tile,
                                      const render::VisibleDryStack& dry, int tile_index, int w,
                                      int h, TileScratch& scratch) {
  scratch.pigments.assign(static_cast<size_t>(pigment_layers_) * 4 * kTileCells, 0.0f);
  if (tile != nullptr) {
    for (int slot = 0; slot < std::min(tile->slot_count(), palette_.pigment_count()); ++slot) {
      const float* amounts = tile->pigment(slot);
      float* layer = scratch.pigments.data() + static_cast<size_t>(slot / 4) * 4 * kTileCells;
      for (int cell = 0; cell < kTileCells; ++cell) layer[4 * cell + slot % 4] = amounts[cell];
    }
  }
  for (int layer = 0; layer < pigment_layers_; ++layer) {
    tile_data_.upload(tile_index, w, h, layer,
                      scratch.pigments.data() + static_cast<size_t>(layer) * 4 * kTileCells,
                      kTileSize);
  }
  // A stroke changes only wet paint: the dry stack's reflectance is baked and uploaded again
  // only when its layers change (or the light, pigments or settings: set_settings).
  std::optional<std::uint64_t>& baked = dry_bakes_[static_cast<std::size_t>(tile_index)];
  if (baked == dry.signature) return;
  // No dry paint (a tile's first wet paint, or its last layer undone): the bare ground.
  const bool bare = dry.layers.empty();
  if (!bare) bake_dry_reflectance(dry, settings_, palette_, scratch.dry_node_major);
  scratch.dry_interleaved.assign(static_cast<size_t>(node_layers_) * 4 * kTileCells, 0.0f);
  for (int node = 0; node < palette_.nodes(); ++node) {
    const float* values = scratch.dry_node_major.data() + static_cast<size_t>(node) * kTileCells;
    const float ground = bare_reflectance_[static_cast<std::size_t>(node)];
    float* layer = scratch.dry_interleaved.data() + static_cast<size_t>(node / 4) * 4 * kTileCells;
    for (int cell = 0; cell < kTileCells; ++cell)
      layer[4 * cell + node % 4] = bare ? ground : values[cell];
  }
  for (int layer = 0; layer < node_layers_; ++layer) {
    tile_data_.upload(tile_index, w, h, pigment_layers_ + layer,
                      scratch.dry_interleaved.data() + static_cast<size_t>(layer) * 4 * kTileCells,
                      kTileSize);
  }
  if (!bare) ++dry_tiles_baked_;
  baked = dry.signature;
}

void CanvasRenderer::upload_all(const paintcore::Canvas& canvas) {
  if (canvas.width_cells() != width_ || canvas.height_cells() != height_) {
    throw std::runtime_error("CanvasRenderer: canvas is " + std::to_string(canvas.width_cells()) +
                             "x" + std::to_string(canvas.height_cells()) + " cells, renderer " +
                             std::to_string(width_) + "x" + std::to_string(height_));
  }
  cell_mm_ = canvas.cell_mm();
  // The places all at once: one allocation, rather than a growth and copy every doubling.
  int painted = 0;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    painted += canvas.tile(index) != nullptr || has_dry_paint(canvas, index) ? 1 : 0;
  }
  tile_data_.reserve(painted);
  TileScratch scratch;
  for (int index = 0; index < canvas.tile_count(); ++index) upload_tile(canvas, index, scratch);
  update_height_range(true);
}

void CanvasRenderer::make_room() {
  tile_data_.reserve(tile_data_.places() + std::max(kRoomTiles, tile_data_.places() / 2));
}

void CanvasRenderer::update_height_range(bool reset) {
  if (tile_max_height_.empty()) return;
  max_height_ = *std::max_element(tile_max_height_.begin(), tile_max_height_.end());
  const float range =
      max_height_ - *std::min_element(tile_min_height_.begin(), tile_min_height_.end());
  height_range_ = reset ? range : std::max(height_range_, range);
}

void CanvasRenderer::upload_tiles(const paintcore::Canvas& canvas,
                                  std::span<const int> tile_indices) {
  cell_mm_ = canvas.cell_mm();
  TileScratch scratch;
  for (int index : tile_indices) {
    if (index < 0 || index >= canvas.tile_count()) {
      throw std::out_of_range("CanvasRenderer: tile index " + std::to_string(index));
    }
    upload_tile(canvas, index, scratch);
  }
  update_height_range(false);
}

void CanvasRenderer::draw(const CanvasView& view, int viewport_w, int viewport_h) {
  update_spread();
  cracks_->prepare(settings_);  // uploads first: an upload binds to the active unit
  pass_->program().use();
  set_uniforms(view, viewport_w, viewport_h);
  pass_->draw();
  check_gl_error("canvas K-M pass");
}

void CanvasRenderer::update_spread() {
  if (!spread_on() || spread_stale_.empty()) return;
  const paintcore::CellRect canvas{0, 0, width_, height_};
  const int radius = spread_->radius();
  const render::relief::Reach reach =
      render::relief::reach(render::relief::relief_params(settings_, cell_mm_, height_range_));
  const int reach_cells = std::max({reach.left, reach.top, reach.right, reach.bottom});
  const paintcore::CellRect mapped = spread_->mapped_box();
  // The change is recomputed within the radius of every cell whose body (the changed cells
  // and the rim their relief reaches) or map changed, where it may be non-zero: near a
  // mapped cell, or where it was written before (a glaze undone).
  const paintcore::CellRect out =
      intersected(intersected(grown(spread_stale_, reach_cells + radius), canvas),
                  united(grown(mapped, radius), spread_written_));
  spread_stale_ = {};
  if (out.empty()) return;
  // The body is needed at the mapped cells within the radius of those.
  const paintcore::CellRect body = intersected(grown(out, radius), mapped);

  GLint framebuffer = 0, viewport[4] = {0, 0, 0, 0}, scissor[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_SCISSOR_BOX, scissor);
  const GLboolean scissor_on = glIsEnabled(GL_SCISSOR_TEST);

  if (!body.empty()) {
    // The body's light, one pixel a cell, linear sRGB: the surface's reflection and the
    // sparkles apart, as render_canvas_with_subsurface renders it.
    spread_->body().bind();
    glEnable(GL_SCISSOR_TEST);
    glScissor(body.x0, height_ - body.y1, body.x1 - body.x0, body.y1 - body.y0);  // GL rows up
    cracks_->prepare(settings_);
    const ShaderProgram& program = pass_->program();
    program.use();
    set_uniforms(one_pixel_per_cell(width_, height_), width_, height_);
    glUniform1i(program.uniform("ghs_reflection"), 0);
    glUniform1i(program.uniform("flake_count"), 0);
    glUniform1i(program.uniform("spread_enabled"), 0);
    glUniform1i(program.uniform("spread_map_view"), 0);
    glUniform1i(program.uniform("linear_srgb_output"), 1);
    pass_->draw();
    check_gl_error("subsurface body pass");
  }
  spread_->spread(out);
  spread_written_ = united(spread_written_, out);

  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
  if (scissor_on == GL_TRUE) {
    glEnable(GL_SCISSOR_TEST);
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
}

void CanvasRenderer::set_uniforms(const CanvasView& view, int viewport_w, int viewport_h) {
  const ShaderProgram& program = pass_->program();
  tile_data_.bind(0, 2);
  surface_.bind(1);
  glUniform1i(program.uniform("tile_data"), 0);
  glUniform1i(program.uniform("surface"), 1);
  glUniform1i(program.uniform("tile_places"), 2);
  glUniform1i(program.uniform("atlas_columns"), tile_data_.columns());
  glUniform1i(program.uniform("dry_first_layer"), pigment_layers_);
  if (display_->bind(program, 3) > GpuSubsurfaceSpread::kDeltaUnit) {
    throw std::runtime_error(
        "GPU renderer: the display transform's lookup tables overlap the "
        "subsurface spread's texture units");
  }

  glUniform2i(program.uniform("canvas_cells"), width_, height_);
  const auto matrix = view.screen_to_cell(viewport_w, viewport_h);
  glUniformMatrix3fv(program.uniform("screen_to_cell"), 1, GL_FALSE, matrix.data());
  glUniform3fv(program.uniform("background"), 1, options_.background_rgb.data());

  // Pigment K and S, slot-major with MAX_NODES per slot, as the shader indexes them.
  const int nodes = palette_.nodes();
  const int slots = palette_.pigment_count();
  glUniform1i(program.uniform("node_count"), nodes);
  glUniform1i(program.uniform("slot_count"), slots);
  std::vector<float> absorption(static_cast<size_t>(paintcore::kMaxPigmentSlots) *
                                render::kMaxNodes);
  std::vector<float> scattering(absorption.size());
  for (int s = 0; s < slots; ++s) {
    std::copy_n(palette_.absorption(s), nodes, absorption.begin() + s * render::kMaxNodes);
    std::copy_n(palette_.scattering(s), nodes, scattering.begin() + s * render::kMaxNodes);
  }
  glUniform1fv(program.uniform("slot_absorption"), static_cast<GLsizei>(absorption.size()),
               absorption.data());
  glUniform1fv(program.uniform("slot_scattering"), static_cast<GLsizei>(scattering.size()),
               scattering.data());
  std::vector<float> to_xyz(static_cast<size_t>(3 * nodes));
  for (int n = 0; n < nodes; ++n) {
    for (int c = 0; c < 3; ++c)
      to_xyz[static_cast<size_t>(3 * n + c)] = palette_.to_display_xyz(c)[n];
  }
  glUniform3fv(program.uniform("node_to_xyz"), nodes, to_xyz.data());
  glUniform3fv(program.uniform("white_xyz"), 1, palette_.white_xyz().data());
  glUniform1fv(program.uniform("bare_reflectance"), nodes, bare_reflectance_.data());
  glUniform1f(program.uniform("optical_per_mm"),
              static_cast<float>(1.0 / settings_.thickness_scale_mm));
  glUniform2f(program.uniform("saunderson_k"),
              settings_.saunderson ? static_cast<float>(settings_.saunderson_k1) : -1.0f,
              static_cast<float>(settings_.saunderson_k2));

  const render::shade::Vec3 to_light = render::shade::light_direction(
      static_cast<float>(settings_.light_azimuth_deg * kRadiansPerDegree),
      static_cast<float>(settings_.light_elevation_deg * kRadiansPerDegree));
  glUniform3f(program.uniform("to_light"), to_light.x, to_light.y, to_light.z);
  glUniform1f(program.uniform("light_intensity"), options_.light_intensity);
  glUniform1f(program.uniform("ambient"), static_cast<float>(settings_.ambient));
  glUniform2f(program.uniform("dry_material"), settings_.dry_material.specular,
              settings_.dry_material.shininess);
  glUniform2f(program.uniform("wet_material"), settings_.wet_material.specular,
              settings_.wet_material.shininess);
  glUniform1f(program.uniform("inverse_gloss_mm"),
              static_cast<float>(1.0 / settings_.wet_gloss_mm));
  glUniform1f(program.uniform("cell_mm"), static_cast<float>(cell_mm_));
  glUniform1i(program.uniform("smooth_zoom"), options_.smooth_zoom ? 1 : 0);

  const render::relief::ReliefParams relief =
      render::relief::relief_params(settings_, cell_mm_, height_range_);
  glUniform1i(program.uniform("relief_shadows"), relief.shadows ? 1 : 0);
  glUniform1i(program.uniform("relief_occlusion"), relief.occlusion ? 1 : 0);
  glUniform2f(program.uniform("relief_step"), relief.step_x, relief.step_y);
  glUniform1f(program.uniform("relief_step_mm"), relief.step_mm);
  glUniform1i(program.uniform("relief_shadow_steps"), relief.shadow_steps);
  glUniform4f(program.uniform("relief_light"), relief.elevation, relief.angular_radius,
              relief.tan_low, relief.tan_high);
  glUniform2i(program.uniform("relief_occlusion_steps"), relief.occlusion_steps_axis,
              relief.occlusion_steps_diagonal);
  glUniform1f(program.uniform("relief_max_height"), max_height_);

  flakes_->bind(program, settings_, cell_mm_);
  cracks_->bind(program, palette_, settings_);
  cracks_->bind_close_up(program, settings_, options_.crack_close_up_min_pixels);
  ghs_->bind(program);
  spread_->bind(program, spread_on(), options_.subsurface_map);
  glUniform1i(program.uniform("linear_srgb_output"), 0);
}

}  // namespace impasto::render_gl
