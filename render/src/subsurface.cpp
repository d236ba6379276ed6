#include "impasto/render/subsurface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include "impasto/render/display.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {
namespace {

using paintcore::kTileCells;
using paintcore::kTileSize;

// The kernel keeps the dipole profile out to this many spread lengths (its tail beyond
// holds a few per cent of the light at most: e^(−σ_tr r)/r²).
constexpr double kSpreadReach = 6.0;

// Thicker than this is no paint layer (a crafted file): not spread.
constexpr float kMaxLayerMm = 100.0f;

// How much each node counts in each linear-sRGB channel: the positive part of the
// palette's readout through XYZ → linear sRGB, normalised per channel.
std::array<std::vector<double>, 3> channel_weights(const SpectralPalette& palette) {
  const auto m = xyz_to_linear_srgb();
  const int nodes = palette.nodes();
  std::array<std::vector<double>, 3> weights;
  for (int c = 0; c < 3; ++c) {
    auto& w = weights[static_cast<std::size_t>(c)];
    w.assign(static_cast<std::size_t>(nodes), 0.0);
    double total = 0.0;
    for (int i = 0; i < nodes; ++i) {
      double v = 0.0;
      for (int k = 0; k < 3; ++k) {
        v += m[static_cast<std::size_t>(3 * c + k)] * palette.to_display_xyz(k)[i];
      }
      w[static_cast<std::size_t>(i)] = std::max(v, 0.0);
      total += std::max(v, 0.0);
    }
    for (double& x : w) x = total > 0.0 ? x / total : 1.0 / nodes;
  }
  return weights;
}

// The top layer of a cell: its volume (mm) and the concentration of each palette pigment.
struct TopLayer {
  float volume_mm = 0.0f;
  std::array<float, paintcore::kMaxPigmentSlots> concentration{};
};

TopLayer top_layer(const paintcore::Canvas& canvas, int tile_index, int cell, int pigments) {
  TopLayer top;
  const paintcore::Tile* tile = canvas.tile(tile_index);
  const auto c = static_cast<std::size_t>(cell);
  if (tile != nullptr && tile->wet_volume_mm[c] > 0.0f) {
    top.volume_mm = tile->wet_volume_mm[c];
    const float inverse = 1.0f / top.volume_mm;
    for (int s = 0; s < std::min(tile->slot_count(), pigments); ++s) {
      top.concentration[static_cast<std::size_t>(s)] =
          pigment_concentration(tile->pigment(s)[c], inverse);
    }
    return top;
  }
  const auto& layers = canvas.dry_layers();
  for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
    const paintcore::DryTile* dry = layer->find(tile_index);
    if (dry == nullptr || dry->volume_mm.size() != static_cast<std::size_t>(kTileCells) ||
        !(dry->volume_mm[c] > 0.0f)) {
      continue;
    }
    top.volume_mm = dry->volume_mm[c];
    const float inverse = 1.0f / top.volume_mm;
    for (std::size_t k = 0; k < dry->slots.size(); ++k) {
      const int slot = dry->slots[k];
      if (slot >= pigments) continue;
      top.concentration[static_cast<std::size_t>(slot)] = pigment_concentration(
          dry->pigment_mm[k * static_cast<std::size_t>(kTileCells) + c], inverse);
    }
    return top;
  }
  return top;
}

// Coefficients and thicknesses on a 2 % logarithmic grid: below what the K-M data resolve,
// and what lets the spread reuse one kernel for the cells of a mix.
double quantised(double value) {
  if (!(value > 0.0)) return 0.0;
  const double step = std::log(1.02);
  return std::exp(std::round(std::log(value) / step) * step);
}

// Cumulative dipole reflectance within radius r: ∫0^r 2πr' R_d(r') dr' in closed form
// (each pole integrates to e^(−σ_tr z) − z e^(−σ_tr d(r))/d(r)).
double cumulative(const dipole::Medium& m, double r) {
  const double extinction = m.absorption_per_mm + m.reduced_scattering_per_mm;
  const double fdr = dipole::diffuse_fresnel_reflectance(m.eta);
  const double a = (1.0 + fdr) / (1.0 - fdr);
  const double sigma_tr = dipole::effective_extinction_per_mm(m);
  const double z_r = 1.0 / extinction;
  const double z_v = z_r * (1.0 + 4.0 * a / 3.0);
  const auto pole = [&](double z) {
    const double d = std::sqrt(r * r + z * z);
    return std::exp(-sigma_tr * z) - z * std::exp(-sigma_tr * d) / d;
  };
  return 0.5 * dipole::reduced_albedo(m) * (pole(z_r) + pole(z_v));
}

}  // namespace

SubsurfaceMap subsurface_map(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                             const RenderSettings& settings) {
  return subsurface_map(canvas, palette, settings,
                        {0, 0, canvas.width_cells(), canvas.height_cells()});
}

SubsurfaceMap subsurface_map(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                             const RenderSettings& settings, const paintcore::CellRect& region) {
  SubsurfaceMap map;
  map.width = canvas.width_cells();
  map.height = canvas.height_cells();
  map.cell_mm = canvas.cell_mm();
  const SurfaceSettings& s = settings.surface;
  if (s.model != SurfaceModel::ghs || !s.subsurface) return map;
  const auto weights = channel_weights(palette);
  const int nodes = palette.nodes();
  const int pigments = std::min(palette.pigment_count(), paintcore::kMaxPigmentSlots);
  const double threshold_mm = s.subsurface_min_cells * map.cell_mm;
  bool have_last = false;
  std::array<float, paintcore::kMaxPigmentSlots> last_concentration{};
  std::array<dipole::Medium, 3> last_media{};
  for (int y = std::max(region.y0, 0); y < std::min(region.y1, map.height); ++y) {
    for (int x = std::max(region.x0, 0); x < std::min(region.x1, map.width); ++x) {
      const int tile_index = (y / kTileSize) * canvas.tiles_x() + x / kTileSize;
      const int cell = (y % kTileSize) * kTileSize + x % kTileSize;
      const TopLayer top = top_layer(canvas, tile_index, cell, pigments);
      // A layer thinner than the threshold cannot spread light that far (its length is at
      // most its thickness): the common case costs this one comparison.
      if (!(top.volume_mm > threshold_mm) || !(top.volume_mm < kMaxLayerMm)) continue;
      SpreadingCell spreading;
      spreading.x = x;
      spreading.y = y;
      spreading.layer_mm = static_cast<float>(quantised(top.volume_mm));
      // The cells of a stroke share their mix: its transport coefficients are made once.
      if (!have_last || top.concentration != last_concentration) {
        for (int c = 0; c < 3; ++c) {
          double absorption = 0.0, scattering = 0.0;
          for (int i = 0; i < nodes; ++i) {
            float k = 0.0f, sc = 0.0f;
            for (int p = 0; p < pigments; ++p) {
              const float conc = top.concentration[static_cast<std::size_t>(p)];
              if (conc > 0.0f) {
                km::accumulate_pigment(conc, palette.absorption(p)[i], palette.scattering(p)[i], k,
                                       sc);
              }
            }
            const double w = weights[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)];
            absorption += w * k;
            scattering += w * sc;
          }
          dipole::Medium medium = dipole::from_kubelka_munk(
              absorption, scattering, settings.thickness_scale_mm, s.binder_index);
          medium.absorption_per_mm = quantised(medium.absorption_per_mm);
          medium.reduced_scattering_per_mm = quantised(medium.reduced_scattering_per_mm);
          last_media[static_cast<std::size_t>(c)] = medium;
        }
        last_concentration = top.concentration;
        have_last = true;
      }
      bool spreads = false;
      for (int c = 0; c < 3; ++c) {
        const dipole::Medium& medium = last_media[static_cast<std::size_t>(c)];
        const double length = spread_length_mm(medium, spreading.layer_mm);
        spreading.medium[static_cast<std::size_t>(c)] = medium;
        spreading.length_cells[static_cast<std::size_t>(c)] =
            static_cast<float>(length / map.cell_mm);
        spreads = spreads || length > threshold_mm;
      }
      if (spreads) map.cells.push_back(spreading);
    }
  }
  return map;
}

bool is_clear_layer(const dipole::Medium& medium, double layer_mm) {
  // The scattering K-M's S stands for, (4/3) S = σ_s' − σ_a/3 (the mapping's K/8 term is
  // absorption's share of the transport picture, not scattering that turns light aside).
  const double scattering = medium.reduced_scattering_per_mm - medium.absorption_per_mm / 3.0;
  return scattering * layer_mm < 1.0;
}

double spread_length_mm(const dipole::Medium& medium, double layer_mm) {
  if (is_clear_layer(medium, layer_mm)) return layer_mm;
  return std::min(dipole::diffusion_length_mm(medium), layer_mm);
}

SpreadKernel spread_kernel(const dipole::Medium& medium, double layer_mm, double cell_mm) {
  SpreadKernel kernel;
  const bool clear = is_clear_layer(medium, layer_mm);
  const double length_mm = spread_length_mm(medium, layer_mm);
  // Clear: light comes back from the ground inside the escape cone, r <= d tan θ_c with
  // sin θ_c = 1/η; the rest is reflected inside (and mostly absorbed by the ground's next
  // bounce or the pigment). Scattering: the dipole out to kSpreadReach lengths.
  const double sin_c = 1.0 / std::max(medium.eta, 1.0 + 1e-9);
  const double reach_mm =
      clear ? layer_mm * sin_c / std::sqrt(1.0 - sin_c * sin_c) : kSpreadReach * length_mm;
  // Every cell with a part within the reach.
  const double reach_cells = reach_mm / cell_mm - 0.5;  // NaN or huge for absurd layers
  kernel.radius = reach_cells > 0.0 ? static_cast<int>(std::ceil(std::min(
                                          reach_cells, static_cast<double>(kSubsurfaceMaxRadius))))
                                    : 0;
  // The profile (per mm²) and its integral out to the reach.
  const double d2 = layer_mm * layer_mm;
  const auto profile = [&](double r) {
    return clear ? d2 / (std::numbers::pi * (r * r + d2) * (r * r + d2))
                 : dipole::profile(medium, r);
  };
  const double total = clear ? 1.0 - d2 / (reach_mm * reach_mm + d2) : cumulative(medium, reach_mm);
  if (kernel.radius == 0 || !(total > 0.0)) {
    kernel.radius = 0;
    kernel.weights = {1.0f};
    return kernel;
  }
  const int side = 2 * kernel.radius + 1;
  kernel.weights.assign(static_cast<std::size_t>(side * side), 0.0f);
  double outside = 0.0;
  for (int dy = -kernel.radius; dy <= kernel.radius; ++dy) {
    for (int dx = -kernel.radius; dx <= kernel.radius; ++dx) {
      if (dx == 0 && dy == 0) continue;
      // The profile averaged over the cell (4 × 4 points): the centre's value alone misses
      // most of a kernel about a cell wide.
      constexpr int kSub = 4;
      double w = 0.0;
      for (int sy = 0; sy < kSub; ++sy) {
        for (int sx = 0; sx < kSub; ++sx) {
          const double r =
              std::hypot(dx + (sx + 0.5) / kSub - 0.5, dy + (sy + 0.5) / kSub - 0.5) * cell_mm;
          if (r <= reach_mm) w += profile(r);
        }
      }
      w *= cell_mm * cell_mm / (kSub * kSub) / total;
      kernel.weights[static_cast<std::size_t>((dy + kernel.radius) * side + dx + kernel.radius)] =
          static_cast<float>(w);
      outside += w;
    }
  }
  if (outside > 1.0) {  // a coarse grid over a steep profile: keep the sum at 1
    for (float& w : kernel.weights) w = static_cast<float>(w / outside);
    outside = 1.0;
  }
  kernel.weights[static_cast<std::size_t>(kernel.radius * side + kernel.radius)] =
      static_cast<float>(1.0 - outside);
  return kernel;
}

void apply_spread(const SubsurfaceMap& map, const Image& body, Image& out) {
  // The map's coefficients are quantised (subsurface_map), so the cells of one stroke share
  // a handful of kernels: each is made once.
  using Key = std::tuple<double, double, double, float>;
  std::map<Key, SpreadKernel> kernels;
  for (const SpreadingCell& cell : map.cells) {
    const float* source = body.pixel(cell.x, cell.y);
    for (int c = 0; c < 3; ++c) {
      const auto k = static_cast<std::size_t>(c);
      const dipole::Medium& medium = cell.medium[k];
      const Key key{medium.absorption_per_mm, medium.reduced_scattering_per_mm, medium.eta,
                    cell.layer_mm};
      auto found = kernels.find(key);
      if (found == kernels.end()) {
        found = kernels.emplace(key, spread_kernel(medium, cell.layer_mm, map.cell_mm)).first;
      }
      const SpreadKernel& kernel = found->second;
      const float light = source[c];
      out.pixel(cell.x, cell.y)[c] -= light;
      for (int dy = -kernel.radius; dy <= kernel.radius; ++dy) {
        for (int dx = -kernel.radius; dx <= kernel.radius; ++dx) {
          const int x = std::clamp(cell.x + dx, 0, map.width - 1);
          const int y = std::clamp(cell.y + dy, 0, map.height - 1);
          out.pixel(x, y)[c] += light * kernel.at(dx, dy);
        }
      }
    }
  }
}

Image subsurface_map_image(const SubsurfaceMap& map) {
  Image image;
  image.width = map.width;
  image.height = map.height;
  image.rgb.assign(3 * static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height),
                   0.0f);
  for (const SpreadingCell& cell : map.cells) {
    for (int c = 0; c < 3; ++c) {
      image.pixel(cell.x, cell.y)[c] = std::min(
          1.0f, cell.length_cells[static_cast<std::size_t>(c)] / kSubsurfaceMapFullScaleCells);
    }
  }
  return image;
}

Image render_painting_with_subsurface(const paintcore::Painting& painting,
                                      const RenderSettings& settings, SubsurfaceMap* map_out) {
  return render_canvas_with_subsurface(painting.canvas(), SpectralPalette(settings, painting),
                                       settings, map_out);
}

Image render_canvas_with_subsurface(const paintcore::Canvas& canvas, const SpectralPalette& palette,
                                    const RenderSettings& settings, SubsurfaceMap* map_out) {
  SubsurfaceMap map = subsurface_map(canvas, palette, settings);
  RenderSettings linear = settings;
  linear.display = DisplayEncoding::linear_srgb;
  TileRenderer renderer(linear, palette);
  renderer.render_all(canvas);
  Image image = renderer.image();
  if (!map.cells.empty()) {
    RenderSettings body = linear;
    body.surface.reflection = false;
    body.flakes = false;
    renderer.set_settings(body, palette);
    renderer.render_all(canvas);
    apply_spread(map, renderer.image(), image);
  }
  if (settings.display != DisplayEncoding::linear_srgb) {
    // Linear sRGB back to XYZ, then the display's own transform (as the renderer's).
    const auto to_xyz = invert_3x3(xyz_to_linear_srgb());
    for (std::size_t p = 0; p < image.rgb.size(); p += 3) {
      const float r = image.rgb[p], g = image.rgb[p + 1], b = image.rgb[p + 2];
      for (std::size_t k = 0; k < 3; ++k) {
        image.rgb[p + k] =
            static_cast<float>(to_xyz[3 * k] * r + to_xyz[3 * k + 1] * g + to_xyz[3 * k + 2] * b);
      }
    }
    DisplayTransform(settings.display).apply(image.rgb.data(), image.rgb.size() / 3);
  }
  if (map_out != nullptr) *map_out = std::move(map);
  return image;
}

}  // namespace impasto::render
