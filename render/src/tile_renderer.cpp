#include "impasto/render/tile_renderer.hpp"

#include <Imath/half.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/render/crack_shading.hpp"
#include "impasto/render/dry_stack.hpp"
#include "impasto/render/flake_shading.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render/shading_key.hpp"
#include "impasto/render/surface_shading.hpp"
#include "spectral_kernels.hpp"

namespace impasto::render {

using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr double kDegreesToRadians = std::numbers::pi / 180.0;

// The pigments of one cell of a layer: slot index and concentration (amount / volume).
template <typename AmountOf>
int gather_shares(int slot_count, float volume_mm, const AmountOf& amount_of,
                  std::array<PigmentShare, paintcore::kMaxPigmentSlots>& shares) {
  int count = 0;
  const float inverse_volume = 1.0f / volume_mm;
  for (int k = 0; k < slot_count; ++k) {
    const auto [slot, amount] = amount_of(k);
    if (amount > 0.0f)
      shares[static_cast<std::size_t>(count++)] = {slot,
                                                   pigment_concentration(amount, inverse_volume)};
  }
  return count;
}

// A rectangle of cells inside one tile, local coordinates, [x0, x1) × [y0, y1).
struct CellRect {
  int x0, y0, x1, y1;
  int area() const { return (x1 - x0) * (y1 - y0); }
};

}  // namespace

struct TileRenderer::TileCache {
  std::vector<float> rgb;  // 3 per cell, display-encoded
  // The dry stack over the ground, nodes per cell; empty when no dry layer touches the tile.
  std::vector<float> dry_f32;
  std::vector<Imath::half> dry_f16;
  bool baked = false;
  std::uint64_t dry_signature = 0;
  // The shading factors of every cell (diffuse, specular) and the wet volume each was
  // computed with: a relight that moves neither the light nor the paint reuses them.
  std::vector<float> shading;
  std::vector<float> shading_wet;
  bool shading_valid = false;
  // The tile's heights were stored from the bare canvas (no tile): the weave alone, the same
  // until paint arrives, so not recomputed.
  bool heights_bare = false;
  std::uint64_t shade_count = 0;
  std::uint64_t flake_cells = 0;  // cells the flake hook looked at
};

TileRenderer::TileRenderer(const RenderSettings& settings, SpectralPalette palette)
    : settings_(settings), palette_(std::move(palette)) {
  validate(settings_);
  display_ = std::make_unique<DisplayTransform>(settings_.display);
  flakes_ = FlakeShading::create(settings_, palette_);
  surface_ = SurfaceShading::create(settings_, palette_);
  lanes_ = std::make_unique<kernels::PaddedPalette>(palette_, settings_);
}

TileRenderer::TileRenderer(const RenderSettings& settings,
                           std::span<const std::string> pigment_slots)
    : TileRenderer(settings, SpectralPalette(settings, pigment_slots)) {}

TileRenderer::~TileRenderer() = default;
TileRenderer::TileRenderer(TileRenderer&&) noexcept = default;
TileRenderer& TileRenderer::operator=(TileRenderer&&) noexcept = default;

void TileRenderer::set_settings(const RenderSettings& settings) {
  set_settings(settings, SpectralPalette(settings, palette_.pigment_names(), palette_.carried()));
}

void TileRenderer::set_settings(const RenderSettings& settings, SpectralPalette palette) {
  validate(settings);
  settings_ = settings;
  palette_ = std::move(palette);
  display_ = std::make_unique<DisplayTransform>(settings_.display);
  flakes_ = FlakeShading::create(settings_, palette_);
  surface_ = SurfaceShading::create(settings_, palette_);
  lanes_ = std::make_unique<kernels::PaddedPalette>(palette_, settings_);
  needs_full_render_ = true;
}

std::uint64_t TileRenderer::shade_count(int tile_index) const {
  return tiles_.at(static_cast<std::size_t>(tile_index)).shade_count;
}

std::uint64_t TileRenderer::flake_cell_count(int tile_index) const {
  return tiles_.at(static_cast<std::size_t>(tile_index)).flake_cells;
}

template <typename Work>
void TileRenderer::run_parallel(std::size_t count, const Work& work) const {
  const auto body = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) work(i);
                      });
  };
  if (settings_.threads > 0) {
    tbb::task_arena arena(settings_.threads);
    arena.execute(body);
  } else {
    body();
  }
}

void TileRenderer::reset_caches(const paintcore::Canvas& canvas) {
  check_render_memory(canvas, "render");
  width_ = canvas.width_cells();
  height_ = canvas.height_cells();
  tiles_x_ = canvas.tiles_x();
  tiles_y_ = canvas.tiles_y();
  cell_mm_ = canvas.cell_mm();
  weave_seed_ = canvas.spec().weave_seed;
  heights_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0.0f);
  tile_min_height_.assign(static_cast<std::size_t>(canvas.tile_count()), 0.0f);
  tile_max_height_.assign(static_cast<std::size_t>(canvas.tile_count()), 0.0f);
  std::vector<TileCache> fresh(static_cast<std::size_t>(canvas.tile_count()));
  for (std::size_t i = 0; i < fresh.size() && i < tiles_.size(); ++i) {
    fresh[i].shade_count = tiles_[i].shade_count;
    fresh[i].flake_cells = tiles_[i].flake_cells;
  }
  tiles_ = std::move(fresh);
}

RenderStats TileRenderer::render_all(const paintcore::Canvas& canvas,
                                     const util::ProgressCallback& progress) {
  if (canvas.width_cells() != width_ || canvas.height_cells() != height_ ||
      canvas.cell_mm() != cell_mm_ || canvas.spec().weave_seed != weave_seed_) {
    reset_caches(canvas);
  }
  for (auto& cache : tiles_) cache.baked = false;  // the light or the nodes may have changed
  std::atomic<bool> heights_changed{false};
  run_parallel(tiles_.size(), [&](std::size_t i) {
    if (store_heights(canvas, static_cast<int>(i))) heights_changed = true;
  });
  update_height_range(true);
  // Same heights, same light direction and shading settings: every cell's shading factors
  // are those cached (a new light spectrum or display only re-does the colour).
  const std::vector<double> key = shading_key();
  const bool reuse_shading = !heights_changed && key == shading_key_;
  shading_key_ = key;
  RenderStats stats;
  std::atomic<std::uint64_t> done{0};
  run_parallel(tiles_.size(), [&](std::size_t i) {
    const int index = static_cast<int>(i);
    bake_dry_stack(canvas, index, tiles_[i]);
    shade_region(canvas, index, 0, 0, kTileSize, kTileSize, tiles_[i], reuse_shading);
    ++tiles_[i].shade_count;
    if (progress) progress(++done, tiles_.size());
  });
  stats.tiles_shaded = stats.tiles_baked = static_cast<int>(tiles_.size());
  needs_full_render_ = false;
  return stats;
}

RenderStats TileRenderer::update(const paintcore::Canvas& canvas,
                                 std::span<const int> changed_tiles) {
  if (needs_full_render_ || canvas.width_cells() != width_ || canvas.height_cells() != height_ ||
      canvas.cell_mm() != cell_mm_ || canvas.spec().weave_seed != weave_seed_) {
    return render_all(canvas);
  }
  std::vector<std::uint8_t> changed(tiles_.size(), 0);
  std::vector<int> order;
  for (int index : changed_tiles) {
    if (index < 0 || index >= static_cast<int>(tiles_.size())) {
      throw std::runtime_error("render update: tile index " + std::to_string(index) +
                               " is outside the canvas's " + std::to_string(tiles_.size()) +
                               " tiles");
    }
    if (!changed[static_cast<std::size_t>(index)]) order.push_back(index);
    changed[static_cast<std::size_t>(index)] = 1;
  }

  // Every shading below reads the new heights, the changed tiles' and their neighbours'.
  run_parallel(order.size(), [&](std::size_t k) { store_heights(canvas, order[k]); });
  update_height_range(false);
  // Every cell whose shading the new heights change is re-shaded below, so the cached
  // shading of the others stays true under the new key (the relief's cuts are exact).
  shading_key_ = shading_key();

  RenderStats stats;
  std::vector<int> baked(order.size(), 0);
  run_parallel(order.size(), [&](std::size_t k) {
    const int index = order[k];
    TileCache& cache = tiles_[static_cast<std::size_t>(index)];
    const bool was_baked = cache.baked;
    const std::uint64_t signature = cache.dry_signature;
    cache.baked = false;
    bake_dry_stack(canvas, index, cache);
    baked[k] = !was_baked || cache.dry_signature != signature;
    shade_region(canvas, index, 0, 0, kTileSize, kTileSize, cache, false);
    ++cache.shade_count;
  });
  stats.tiles_shaded = static_cast<int>(order.size());
  for (int b : baked) stats.tiles_baked += b;

  // The rims of unchanged tiles whose shading reads heights of the changed tiles: the
  // normals' one-cell rim, the occlusion radius, and the shadows downstream of the light.
  // One rectangle a tile: the box around every rim that falls in it.
  std::vector<CellRect> rims(tiles_.size(), CellRect{kTileSize, kTileSize, 0, 0});
  const relief::Reach reach = relief::reach(relief_);
  for (int index : order) {
    const int gx0 = std::max(0, (index % tiles_x_) * kTileSize - reach.left);
    const int gy0 = std::max(0, (index / tiles_x_) * kTileSize - reach.top);
    const int gx1 = std::min(width_, (index % tiles_x_ + 1) * kTileSize + reach.right);
    const int gy1 = std::min(height_, (index / tiles_x_ + 1) * kTileSize + reach.bottom);
    for (int ny = gy0 / kTileSize; ny <= (gy1 - 1) / kTileSize; ++ny) {
      for (int nx = gx0 / kTileSize; nx <= (gx1 - 1) / kTileSize; ++nx) {
        const int neighbour = ny * tiles_x_ + nx;
        if (changed[static_cast<std::size_t>(neighbour)]) continue;
        CellRect& rim = rims[static_cast<std::size_t>(neighbour)];
        rim.x0 = std::min(rim.x0, std::max(gx0 - nx * kTileSize, 0));
        rim.y0 = std::min(rim.y0, std::max(gy0 - ny * kTileSize, 0));
        rim.x1 = std::max(rim.x1, std::min(gx1 - nx * kTileSize, kTileSize));
        rim.y1 = std::max(rim.y1, std::min(gy1 - ny * kTileSize, kTileSize));
      }
    }
  }
  std::vector<int> rim_tiles;
  for (std::size_t i = 0; i < rims.size(); ++i) {
    if (rims[i].x1 > rims[i].x0 && rims[i].y1 > rims[i].y0) {
      rim_tiles.push_back(static_cast<int>(i));
    }
  }
  run_parallel(rim_tiles.size(), [&](std::size_t k) {
    const int index = rim_tiles[k];
    const CellRect& r = rims[static_cast<std::size_t>(index)];
    shade_region(canvas, index, r.x0, r.y0, r.x1, r.y1, tiles_[static_cast<std::size_t>(index)],
                 false);
  });
  for (int index : rim_tiles) stats.border_cells += rims[static_cast<std::size_t>(index)].area();
  return stats;
}

bool TileRenderer::store_heights(const paintcore::Canvas& canvas, int tile_index) {
  const paintcore::Tile* tile = canvas.tile(tile_index);
  TileCache& cache = tiles_[static_cast<std::size_t>(tile_index)];
  if (tile == nullptr && cache.heights_bare) return false;
  cache.heights_bare = tile == nullptr;
  const int origin_x = (tile_index % tiles_x_) * kTileSize;
  const int origin_y = (tile_index / tiles_x_) * kTileSize;
  const int columns = std::min(kTileSize, width_ - origin_x);
  const int rows = std::min(kTileSize, height_ - origin_y);
  float lowest = std::numeric_limits<float>::max();
  float highest = std::numeric_limits<float>::lowest();
  bool changed = false;
  for (int y = 0; y < rows; ++y) {
    float* row =
        &heights_[static_cast<std::size_t>(origin_y + y) * static_cast<std::size_t>(width_) +
                  static_cast<std::size_t>(origin_x)];
    for (int x = 0; x < columns; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      const float before = row[x];
      row[x] = tile != nullptr ? paintcore::surface_height_mm(*tile, static_cast<int>(c))
                               : canvas.base_height_mm(origin_x + x, origin_y + y);
      changed |= std::bit_cast<std::uint32_t>(before) != std::bit_cast<std::uint32_t>(row[x]);
      lowest = std::min(lowest, row[x]);
      highest = std::max(highest, row[x]);
    }
  }
  tile_min_height_[static_cast<std::size_t>(tile_index)] = lowest;
  tile_max_height_[static_cast<std::size_t>(tile_index)] = highest;
  return changed;
}

std::vector<double> TileRenderer::shading_key() const {
  // The settings' part (shading_key.hpp, shared with the window's cached view), then what
  // the relief's marches were derived for: the cell size and the height range.
  std::vector<double> key = shading_settings_key(settings_);
  const auto& r = relief_;
  key.insert(key.end(),
             {r.step_x, r.step_y, r.step_mm, static_cast<double>(r.shadow_steps), r.elevation,
              r.angular_radius, r.tan_low, r.tan_high, static_cast<double>(r.occlusion_steps_axis),
              static_cast<double>(r.occlusion_steps_diagonal), r.cell_mm, max_height_, cell_mm_});
  return key;
}

void TileRenderer::update_height_range(bool reset) {
  max_height_ = *std::max_element(tile_max_height_.begin(), tile_max_height_.end());
  const float range =
      max_height_ - *std::min_element(tile_min_height_.begin(), tile_min_height_.end());
  height_range_ = reset ? range : std::max(height_range_, range);
  relief_ = relief::relief_params(settings_, cell_mm_, height_range_);
}

void TileRenderer::bake_dry_stack(const paintcore::Canvas& canvas, int tile_index,
                                  TileCache& cache) const {
  const VisibleDryStack stack = visible_dry_stack(canvas, tile_index, palette_);
  const std::vector<const paintcore::DryTile*>& layers = stack.layers;
  const std::uint64_t signature = stack.signature;
  if (cache.baked && signature == cache.dry_signature) return;
  cache.dry_signature = signature;
  cache.baked = true;
  cache.dry_f32.clear();
  cache.dry_f16.clear();
  if (layers.empty()) return;  // the ground alone: nothing stored

  const int nodes = palette_.nodes();
  const auto values = static_cast<std::size_t>(kTileCells) * static_cast<std::size_t>(nodes);
  const bool half = settings_.storage == ReflectanceStorage::float16;
  if (half) {
    cache.dry_f16.resize(values);
  } else {
    cache.dry_f32.resize(values);
  }
  const auto inverse_scale = static_cast<float>(1.0 / settings_.thickness_scale_mm);
  if (fast_kernels()) {
    // Every cell at once, padded per cell, then packed to `nodes` per cell.
    const auto padded = static_cast<std::size_t>(lanes_->padded);
    // 128 KiB a tile at 8 nodes: kept per thread, not mapped and unmapped for every tile.
    thread_local std::vector<float> stack;
    stack.resize(static_cast<std::size_t>(kTileCells) * padded);
    for (int c = 0; c < kTileCells; ++c) {
      std::copy(lanes_->ground.begin(), lanes_->ground.end(),
                stack.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(c) * padded));
    }
    for (const paintcore::DryTile* dry : layers) {
      std::array<int, paintcore::kMaxPigmentSlots> pigments{};
      std::array<const float*, paintcore::kMaxPigmentSlots> amounts{};
      const int slots = static_cast<int>(std::min(dry->slots.size(), pigments.size()));
      for (int k = 0; k < slots; ++k) {
        pigments[static_cast<std::size_t>(k)] = dry->slots[static_cast<std::size_t>(k)];
        amounts[static_cast<std::size_t>(k)] =
            &dry->pigment_mm[static_cast<std::size_t>(k) * kTileCells];
      }
      kernels::composite_layer_cells(
          *lanes_, {dry->volume_mm.data(), slots, pigments.data(), amounts.data()}, kTileCells,
          inverse_scale, stack.data());
    }
    for (int c = 0; c < kTileCells; ++c) {
      const float* from = &stack[static_cast<std::size_t>(c) * padded];
      const std::size_t base = static_cast<std::size_t>(c) * static_cast<std::size_t>(nodes);
      if (half) {
        for (int i = 0; i < nodes; ++i) {
          cache.dry_f16[base + static_cast<std::size_t>(i)] = Imath::half(from[i]);
        }
      } else {
        std::copy_n(from, nodes, &cache.dry_f32[base]);
      }
    }
    return;
  }
  // One value per node; the full spectrum has hundreds, so on the heap, once per tile.
  std::vector<float> node_values(static_cast<std::size_t>(nodes));
  float* reflectance = node_values.data();
  for (int c = 0; c < kTileCells; ++c) {
    composite_dry_stack(palette_, layers, c, inverse_scale, reflectance);
    const std::size_t base = static_cast<std::size_t>(c) * static_cast<std::size_t>(nodes);
    for (int i = 0; i < nodes; ++i) {
      if (half) {
        cache.dry_f16[base + static_cast<std::size_t>(i)] = Imath::half(reflectance[i]);
      } else {
        cache.dry_f32[base + static_cast<std::size_t>(i)] = reflectance[i];
      }
    }
  }
}

// The light at a cell (light_at).
struct TileRenderer::CellLight {
  shade::Vec3 normal;
  shade::Visibility visibility;
  shade::Shading shading;
};

// What shading a region of one tile shares, whichever path shades it.
struct TileRenderer::RegionShading {
  const paintcore::Canvas& canvas;
  int tile_index;
  const paintcore::Tile* tile;  // nullptr where nothing was ever painted
  int x0, y0, x1, y1;           // the region, in the tile's cells
  int origin_x, origin_y;       // the tile's first cell on the canvas
  relief::HeightField field;
  int nodes;
  float inverse_scale, inverse_gloss, cell_mm, ambient, k1, k2;
  float sky;  // the sky's reflection in the paint's surface (shade::blinn_phong)
  shade::Vec3 to_light;
  const std::array<float, 3>& white;
  bool has_dry;
};

// The relief's light at a cell, the one shading both paths give it: its normal from the heights
// around it, the shadow and occlusion the relief casts, and Blinn-Phong's diffuse and specular
// factors for its gloss (wet paint shines).
TileRenderer::CellLight TileRenderer::light_at(const RegionShading& r, int gx, int gy,
                                               float wet_volume) const {
  CellLight light;
  light.normal = shade::height_normal(r.field.at(gx - 1, gy), r.field.at(gx + 1, gy),
                                      r.field.at(gx, gy - 1), r.field.at(gx, gy + 1), r.cell_mm);
  const shade::Material material =
      shade::blend(settings_.dry_material, settings_.wet_material, wet_volume * r.inverse_gloss);
  if (relief_.shadows)
    light.visibility.shadow = relief::shadow(r.field, gx, gy, max_height_, relief_);
  if (relief_.occlusion) light.visibility.occlusion = relief::occlusion(r.field, gx, gy, relief_);
  light.shading =
      shade::blinn_phong(light.normal, r.to_light, r.ambient, material, light.visibility, r.sky);
  return light;
}

// The display transform of the rows done: one call for a whole tile, else one a row.
void TileRenderer::display_rows(const RegionShading& r, int y, TileCache& cache) const {
  if (r.x0 == 0 && r.x1 == kTileSize && y == r.y1 - 1) {
    display_->apply(&cache.rgb[3 * static_cast<std::size_t>(r.y0 * kTileSize)],
                    static_cast<std::size_t>((r.y1 - r.y0) * kTileSize));
  } else if (!(r.x0 == 0 && r.x1 == kTileSize)) {
    display_->apply(&cache.rgb[3 * static_cast<std::size_t>(y * kTileSize + r.x0)],
                    static_cast<std::size_t>(r.x1 - r.x0));
  }
}

void TileRenderer::shade_region(const paintcore::Canvas& canvas, int tile_index, int x0, int y0,
                                int x1, int y1, TileCache& cache, bool may_reuse_shading) const {
  const paintcore::Tile* tile = canvas.tile(tile_index);
  if (tile != nullptr && tile->slot_count() > palette_.pigment_count()) {
    throw std::runtime_error("render: tile " + std::to_string(tile_index) + " holds " +
                             std::to_string(tile->slot_count()) +
                             " pigment slots but the palette has " +
                             std::to_string(palette_.pigment_count()) + " pigments");
  }
  if (cache.rgb.empty()) cache.rgb.assign(3 * static_cast<std::size_t>(kTileCells), 0.0f);
  const RegionShading region{
      canvas,
      tile_index,
      tile,
      x0,
      y0,
      x1,
      y1,
      (tile_index % tiles_x_) * kTileSize,
      (tile_index / tiles_x_) * kTileSize,
      relief::HeightField{heights_.data(), width_, height_},
      palette_.nodes(),
      static_cast<float>(1.0 / settings_.thickness_scale_mm),
      static_cast<float>(1.0 / settings_.wet_gloss_mm),
      static_cast<float>(cell_mm_),
      static_cast<float>(settings_.ambient),
      static_cast<float>(settings_.saunderson_k1),
      static_cast<float>(settings_.saunderson_k2),
      settings_.saunderson ? static_cast<float>(settings_.saunderson_k1) : 0.0f,
      shade::light_direction(static_cast<float>(settings_.light_azimuth_deg * kDegreesToRadians),
                             static_cast<float>(settings_.light_elevation_deg * kDegreesToRadians)),
      palette_.white_xyz(),
      !cache.dry_f32.empty() || !cache.dry_f16.empty()};
  // Flake sparkles: inactive (no per-cell work) where the tile holds no flake pigment.
  FlakeTileView flakes = flakes_ ? flakes_->tile(canvas, tile_index) : FlakeTileView{};
  // Cracks: inactive (no per-cell work) where the tile has no crack.
  const bool cracked_tile = settings_.cracks && canvas.cracks().tile(tile_index) != nullptr;
  if (fast_kernels() && !surface_ && !cracked_tile) {
    shade_with_kernels(region, cache, flakes, may_reuse_shading);
  } else {
    shade_cell_by_cell(region, cache, flakes);
  }
  cache.flake_cells += flakes.cells_evaluated();
}

// A row at a time: the colour of every cell through the spectral kernels, then the shading
// factors (cached, or computed and cached), then both combined.
void TileRenderer::shade_with_kernels(const RegionShading& r, TileCache& cache,
                                      FlakeTileView& flakes, bool may_reuse_shading) const {
  const paintcore::Tile* tile = r.tile;
  const auto padded = static_cast<std::size_t>(lanes_->padded);
  const int columns = r.x1 - r.x0;
  std::vector<float> row_reflectance(static_cast<std::size_t>(kTileSize) * padded, 0.0f);
  std::array<float, 3 * kTileSize> row_xyz{};
  std::array<int, paintcore::kMaxPigmentSlots> slots{};
  for (int k = 0; k < paintcore::kMaxPigmentSlots; ++k) slots[static_cast<std::size_t>(k)] = k;
  if (cache.shading.empty()) {
    cache.shading.assign(2 * static_cast<std::size_t>(kTileCells), 0.0f);
    cache.shading_wet.assign(static_cast<std::size_t>(kTileCells), 0.0f);
  }
  // The cached factors hold for this light and these heights (may_reuse_shading) if the
  // wet paint, which sets the gloss, is the same too.
  const bool reuse =
      may_reuse_shading && cache.shading_valid &&
      (tile != nullptr
           ? std::equal(tile->wet_volume_mm.begin(), tile->wet_volume_mm.end(),
                        cache.shading_wet.begin(),
                        [](float a, float b) {
                          return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
                        })
           : std::all_of(cache.shading_wet.begin(), cache.shading_wet.end(),
                         [](float w) { return std::bit_cast<std::uint32_t>(w) == 0; }));
  // Bare canvas (no paint, no dry layer): one colour for the whole tile.
  const bool bare = tile == nullptr && !r.has_dry;
  if (bare) {
    std::copy_n(lanes_->ground.data(), padded, row_reflectance.data());
    kernels::cells_to_xyz(*lanes_, row_reflectance.data(), 1, row_xyz.data());
    for (int x = 1; x < columns; ++x)
      std::copy_n(row_xyz.data(), 3, &row_xyz[3 * static_cast<std::size_t>(x)]);
  }
  for (int y = r.y0; y < r.y1; ++y) {
    const int first = y * kTileSize + r.x0;
    for (int x = 0; x < columns && !bare; ++x) {
      float* reflectance = &row_reflectance[static_cast<std::size_t>(x) * padded];
      const std::size_t base =
          static_cast<std::size_t>(first + x) * static_cast<std::size_t>(r.nodes);
      if (!r.has_dry) {
        std::copy_n(lanes_->ground.data(), padded, reflectance);
      } else if (cache.dry_f32.empty()) {
        for (int i = 0; i < r.nodes; ++i) {
          reflectance[i] = static_cast<float>(cache.dry_f16[base + static_cast<std::size_t>(i)]);
        }
      } else {
        std::copy_n(&cache.dry_f32[base], r.nodes, reflectance);
      }
    }
    if (tile != nullptr) {
      std::array<const float*, paintcore::kMaxPigmentSlots> amounts{};
      for (int k = 0; k < tile->slot_count(); ++k) {
        amounts[static_cast<std::size_t>(k)] = tile->pigment(k) + first;
      }
      kernels::composite_layer_cells(*lanes_,
                                     {&tile->wet_volume_mm[static_cast<std::size_t>(first)],
                                      tile->slot_count(), slots.data(), amounts.data()},
                                     columns, r.inverse_scale, row_reflectance.data());
    }
    if (!bare) kernels::cells_to_xyz(*lanes_, row_reflectance.data(), columns, row_xyz.data());
    for (int x = r.x0; x < r.x1; ++x) {
      const int c = y * kTileSize + x;
      const auto cell = static_cast<std::size_t>(c);
      const float wet_volume = tile != nullptr ? tile->wet_volume_mm[cell] : 0.0f;
      const int gx = r.origin_x + x;
      const int gy = r.origin_y + y;
      float* factors = &cache.shading[2 * cell];
      if (!reuse) {
        const shade::Shading shading = light_at(r, gx, gy, wet_volume).shading;
        factors[0] = shading.diffuse;
        factors[1] = shading.specular;
        cache.shading_wet[cell] = wet_volume;
      }
      const float* xyz = &row_xyz[3 * static_cast<std::size_t>(x - r.x0)];
      float* out = &cache.rgb[3 * cell];
      for (int ch = 0; ch < 3; ++ch) {
        out[ch] = xyz[ch] * factors[0] + r.white[static_cast<std::size_t>(ch)] * factors[1];
      }
      if (flakes.active()) {
        const shade::Vec3 normal =
            shade::height_normal(r.field.at(gx - 1, gy), r.field.at(gx + 1, gy),
                                 r.field.at(gx, gy - 1), r.field.at(gx, gy + 1), r.cell_mm);
        flakes.add_cell(c, gx, gy, normal, r.field.at(gx, gy), wet_volume, out);
      }
    }
    display_rows(r, y, cache);
  }
  // Cells shaded in place keep the cache whole; a tile's first shading is a whole tile.
  if (r.x0 == 0 && r.y0 == 0 && r.x1 == kTileSize && r.y1 == kTileSize) cache.shading_valid = true;
}

// A cell at a time, one wavelength node at a time (kubelka_munk_cell.hpp): the reference the
// kernels are tested against, and the path of cracks and the ghs surface model.
void TileRenderer::shade_cell_by_cell(const RegionShading& r, TileCache& cache,
                                      FlakeTileView& flakes) const {
  const paintcore::Tile* tile = r.tile;
  cache.shading_valid = false;  // this path keeps no shading factors
  CrackTileShading cracks(r.canvas, r.tile_index, settings_, palette_.ground(), r.nodes);
  std::array<PigmentShare, paintcore::kMaxPigmentSlots> shares{};
  std::vector<float> node_values(static_cast<std::size_t>(r.nodes));
  float* reflectance = node_values.data();
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const int c = y * kTileSize + x;
      const auto cell = static_cast<std::size_t>(c);
      // The dry stack over the ground, baked for this light.
      const std::size_t base = cell * static_cast<std::size_t>(r.nodes);
      for (int i = 0; i < r.nodes; ++i) {
        const auto k = base + static_cast<std::size_t>(i);
        reflectance[i] = !r.has_dry              ? palette_.ground()[i]
                         : cache.dry_f32.empty() ? static_cast<float>(cache.dry_f16[k])
                                                 : cache.dry_f32[k];
      }
      const bool cracked = cracks.active() && cracks.take_walls(c, reflectance);
      // The wet layer on top.
      float wet_volume = 0.0f;
      if (tile != nullptr) {
        wet_volume = tile->wet_volume_mm[cell];
        if (wet_volume > 0.0f) {
          const int count = gather_shares(
              tile->slot_count(), wet_volume,
              [&](int slot) {
                return std::pair{slot, tile->pigment(slot)[cell]};
              },
              shares);
          composite_paint_layer(palette_, std::span(shares.data(), static_cast<std::size_t>(count)),
                                wet_volume * r.inverse_scale, reflectance);
        }
      }
      if (cracked) cracks.blend(reflectance);
      if (settings_.saunderson) {
        for (int i = 0; i < r.nodes; ++i)
          reflectance[i] = km::saunderson(reflectance[i], r.k1, r.k2);
      }
      float xyz[3];
      node_reflectance_to_xyz(palette_, reflectance, xyz);

      // Shading from the total height around the cell, the light the relief lets through.
      const int gx = r.origin_x + x;
      const int gy = r.origin_y + y;
      const CellLight light = light_at(r, gx, gy, wet_volume);
      float* out = &cache.rgb[3 * cell];
      if (surface_) {  // the ghs surface model (surface_shading.hpp) in place of Blinn-Phong
        surface_->shade(light.normal, r.to_light, light.visibility, wet_volume * r.inverse_gloss,
                        paintcore::cell_surface(tile, c), reflectance, out);
      } else {
        for (int ch = 0; ch < 3; ++ch) {
          out[ch] = xyz[ch] * light.shading.diffuse +
                    r.white[static_cast<std::size_t>(ch)] * light.shading.specular;
        }
      }
      if (flakes.active()) {
        flakes.add_cell(c, gx, gy, light.normal, r.field.at(gx, gy), wet_volume, out);
      }
    }
    display_rows(r, y, cache);  // XYZ to the display
  }
}

Image TileRenderer::image() const {
  Image image;
  image.width = width_;
  image.height = height_;
  image.rgb.assign(3 * static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0.0f);
  // A row of tiles a task: the copy is memory-bound, and 200 ms on one core at 4096².
  run_parallel(static_cast<std::size_t>(tiles_y_), [&](std::size_t row) {
    const int ty = static_cast<int>(row);
    for (int tx = 0; tx < tiles_x_; ++tx) {
      const TileCache& cache = tiles_[static_cast<std::size_t>(ty * tiles_x_ + tx)];
      if (cache.rgb.empty()) continue;
      for (int y = 0; y < kTileSize && ty * kTileSize + y < height_; ++y) {
        const int columns = std::min(kTileSize, width_ - tx * kTileSize);
        std::copy_n(&cache.rgb[3 * static_cast<std::size_t>(y * kTileSize)], 3 * columns,
                    image.pixel(tx * kTileSize, ty * kTileSize + y));
      }
    }
  });
  return image;
}

}  // namespace impasto::render
