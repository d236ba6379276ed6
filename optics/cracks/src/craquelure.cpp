// The craquelure generator: a jittered Voronoi network of islands, cracks sized by film
// thickness and age.
#include "impasto/cracks/craquelure.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "impasto/cracks/philox_rng.hpp"

namespace impasto::cracks {

namespace {
constexpr std::uint32_t kStreamSites = 11, kStreamEdges = 12;
constexpr int kMargin = 2;  // site rows beyond the canvas, so border islands are whole

void check_settings(const CraquelureSettings& s) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::runtime_error(std::string("craquelure ") + name + " must be finite and > 0");
    }
  };
  positive(s.island_size_mm, "island_size_mm");
  positive(s.max_strain, "max_strain");
  positive(s.strain_time_years, "strain_time_years");
  positive(s.years_to_ground, "years_to_ground");
  positive(s.reference_thickness_mm, "reference_thickness_mm");
  if (!(s.age_years >= 0.0) || !std::isfinite(s.age_years)) {
    throw std::runtime_error("craquelure age_years must be finite and >= 0");
  }
  if (!(s.jitter >= 0.0 && s.jitter <= 1.0)) {
    throw std::runtime_error("craquelure jitter must be in [0, 1]");
  }
  if (!(s.width_variation >= 0.0 && s.width_variation < 1.0)) {
    throw std::runtime_error("craquelure width_variation must be in [0, 1)");
  }
}

// Jittered island sites on a grid of pitch island_size_mm, with a margin around the canvas.
class SiteGrid {
 public:
  SiteGrid(const CrackMap& map, const CraquelureSettings& s) : pitch_(s.island_size_mm) {
    nx_ = static_cast<int>(std::ceil(map.width() * map.cell_mm() / pitch_)) + 2 * kMargin;
    ny_ = static_cast<int>(std::ceil(map.height() * map.cell_mm() / pitch_)) + 2 * kMargin;
    if (static_cast<double>(nx_) * ny_ > 1e8) {
      throw std::runtime_error("craquelure island_size_mm is too small for the canvas");
    }
    sites_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int gy = 0; gy < ny_; ++gy) {
      for (int gx = 0; gx < nx_; ++gx) {
        const std::size_t id = static_cast<std::size_t>(gy) * nx_ + gx;
        const UniformBlock u = uniforms(s.seed, kStreamSites, id, 0);
        sites_[id] = {(gx - kMargin + 0.5 + s.jitter * (u.u[0] - 0.5)) * pitch_,
                      (gy - kMargin + 0.5 + s.jitter * (u.u[1] - 0.5)) * pitch_};
      }
    }
  }

  // Index of the site nearest to (x, y) mm; ties go to the lower index. With jitter <= 1 the
  // nearest site lies within two grid cells.
  std::uint32_t nearest(double x, double y) const {
    const int cx = static_cast<int>(std::floor(x / pitch_)) + kMargin;
    const int cy = static_cast<int>(std::floor(y / pitch_)) + kMargin;
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_id = 0;
    for (int gy = std::max(cy - 2, 0); gy <= std::min(cy + 2, ny_ - 1); ++gy) {
      for (int gx = std::max(cx - 2, 0); gx <= std::min(cx + 2, nx_ - 1); ++gx) {
        const std::size_t id = static_cast<std::size_t>(gy) * nx_ + gx;
        const double dx = sites_[id][0] - x, dy = sites_[id][1] - y;
        const double d2 = dx * dx + dy * dy;
        if (d2 < best) {
          best = d2;
          best_id = static_cast<std::uint32_t>(id);
        }
      }
    }
    return best_id;
  }

 private:
  double pitch_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::array<double, 2>> sites_;
};

// The dry layer reached at depth_mm below the top of the film (or the canvas ground).
std::uint8_t layer_at_depth(const PaintFilm& film, std::size_t cell, double depth_mm) {
  if (film.layer_thickness_mm.empty()) {
    return depth_mm < film.uniform_thickness_mm ? 0 : kCanvasGround;
  }
  double below_top = 0.0;
  for (std::size_t k = film.layer_thickness_mm.size(); k-- > 0;) {
    below_top += film.layer_thickness_mm[k][cell];
    if (depth_mm < below_top) return static_cast<std::uint8_t>(std::min<std::size_t>(k, 254));
  }
  return kCanvasGround;
}

double film_thickness(const PaintFilm& film, std::size_t cell) {
  if (film.layer_thickness_mm.empty()) return film.uniform_thickness_mm;
  double t = 0.0;
  for (const auto& layer : film.layer_thickness_mm) t += layer[cell];
  return t;
}

// Keeps the largest 8-connected network, dropping fragments cut off by the canvas border.
void keep_largest_network(CrackMap& map) {
  const int w = map.width(), h = map.height();
  std::vector<std::int32_t> label(static_cast<std::size_t>(w) * h, -1);
  std::vector<std::size_t> sizes;
  std::vector<std::pair<int, int>> stack;
  map.for_each_crack([&](int x0, int y0, const CrackCell&) {
    if (label[static_cast<std::size_t>(y0) * w + x0] >= 0) return;
    const auto id = static_cast<std::int32_t>(sizes.size());
    sizes.push_back(0);
    label[static_cast<std::size_t>(y0) * w + x0] = id;
    stack.push_back({x0, y0});
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      ++sizes.back();
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          auto& l = label[static_cast<std::size_t>(ny) * w + nx];
          if (l >= 0 || !map.at(nx, ny).has_crack()) continue;
          l = id;
          stack.push_back({nx, ny});
        }
      }
    }
  });
  if (sizes.size() <= 1) return;
  const auto keep =
      static_cast<std::int32_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::int32_t l = label[static_cast<std::size_t>(y) * w + x];
      if (l >= 0 && l != keep) map.set(x, y, CrackCell{});
    }
  }
}
}  // namespace

CrackSize craquelure_crack_size(const CraquelureSettings& s, double thickness_mm,
                                double variation) {
  const double strain = s.max_strain * (1.0 - std::exp(-s.age_years / s.strain_time_years));
  const double opening =
      strain * s.island_size_mm * (thickness_mm / s.reference_thickness_mm) * variation;
  return {thickness_mm * std::min(1.0, s.age_years / s.years_to_ground), 0.5 * opening};
}

void generate_craquelure(CrackMap& map, const PaintFilm& film, const CraquelureSettings& s) {
  check_settings(s);
  const std::size_t cells = static_cast<std::size_t>(map.width()) * map.height();
  for (std::size_t k = 0; k < film.layer_thickness_mm.size(); ++k) {
    if (film.layer_thickness_mm[k].size() != cells) {
      throw std::runtime_error("paint film layer " + std::to_string(k) + " has " +
                               std::to_string(film.layer_thickness_mm[k].size()) +
                               " cells, the crack map " + std::to_string(cells));
    }
  }
  for (std::size_t k = 0; k < film.layer_thickness_mm.size(); ++k) {
    const auto& layer = film.layer_thickness_mm[k];
    for (std::size_t i = 0; i < layer.size(); ++i) {
      if (!(layer[i] >= 0.0f) || !std::isfinite(layer[i])) {
        throw std::runtime_error(
            "paint film layer " + std::to_string(k) + " cell (" + std::to_string(i % map.width()) +
            ", " + std::to_string(i / map.width()) + "): thickness must be finite and >= 0");
      }
    }
  }
  if (film.layer_thickness_mm.empty() &&
      (!(film.uniform_thickness_mm >= 0.0) || !std::isfinite(film.uniform_thickness_mm))) {
    throw std::runtime_error("paint film uniform_thickness_mm must be finite and >= 0");
  }
  const SiteGrid sites(map, s);
  const double h = map.cell_mm();
  const int w = map.width();
  const int bands = map.tiles_y();
  // Each band of 64 rows is computed in parallel; cells are stored in band order.
  struct Found {
    int x, y;
    CrackCell cell;
  };
  std::vector<std::vector<Found>> found(static_cast<std::size_t>(bands));
  tbb::parallel_for(0, bands, [&](int band) {
    const int y0 = band * CrackMap::kTileSize;
    const int y1 = std::min(map.height(), y0 + CrackMap::kTileSize);
    std::vector<std::uint32_t> above(static_cast<std::size_t>(w) + 1), below(above.size());
    for (int x = 0; x <= w; ++x) above[x] = sites.nearest(x * h, y0 * h);
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x <= w; ++x) below[x] = sites.nearest(x * h, (y + 1) * h);
      for (int x = 0; x < w; ++x) {
        const std::uint32_t c[4] = {above[x], above[x + 1], below[x], below[x + 1]};
        const auto [lo, hi] = std::minmax_element(c, c + 4);
        if (*lo == *hi) continue;
        const std::size_t cell = static_cast<std::size_t>(y) * w + x;
        const double t = film_thickness(film, cell);
        if (t < 1e-3) continue;
        // Each crack (a pair of islands) gets its own width factor.
        const std::uint64_t pair = (std::uint64_t{*lo} << 32) | *hi;
        const double v =
            1.0 + s.width_variation * (2.0 * uniforms(s.seed, kStreamEdges, pair, 0).u[0] - 1.0);
        const CrackSize size = craquelure_crack_size(s, t, v);
        if (!(size.depth_mm > 0.0) || !(size.half_width_mm > 0.0)) continue;
        found[band].push_back(
            {x, y,
             CrackCell{static_cast<float>(size.depth_mm), static_cast<float>(size.half_width_mm),
                       s.shape, layer_at_depth(film, cell, size.depth_mm)}});
      }
      std::swap(above, below);
    }
  });
  // The new network is pruned on its own, so cracks already in the map are kept; where the
  // two meet the deeper crack stays.
  CrackMap fresh(map.width(), map.height(), map.cell_mm());
  for (const auto& band : found) {
    for (const Found& f : band) fresh.set(f.x, f.y, f.cell);
  }
  keep_largest_network(fresh);
  fresh.for_each_crack([&](int x, int y, const CrackCell& c) {
    if (map.at(x, y).depth_mm < c.depth_mm) map.set(x, y, c);
  });
}

void stamp_crack(CrackMap& map, const CrackStroke& stroke) {
  validate(CavityDims{stroke.depth_mm, stroke.half_width_mm});
  const double h = map.cell_mm();
  const double reach = stroke.half_width_mm + 0.5 * h;
  const CrackCell crack{static_cast<float>(stroke.depth_mm),
                        static_cast<float>(stroke.half_width_mm), stroke.shape,
                        stroke.exposed_layer};
  for (const auto& p : stroke.points_mm) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) {
      throw std::runtime_error("crack stroke point is not finite");
    }
  }
  for (std::size_t i = 0; i < stroke.points_mm.size(); ++i) {
    const auto a = stroke.points_mm[i];
    const auto b = stroke.points_mm[std::min(i + 1, stroke.points_mm.size() - 1)];
    // Cells in the segment's bounding box, grown by the reach.
    const int x0 = std::max(0, static_cast<int>(std::floor((std::min(a[0], b[0]) - reach) / h)));
    const int x1 =
        std::min(map.width() - 1, static_cast<int>(std::floor((std::max(a[0], b[0]) + reach) / h)));
    const int y0 = std::max(0, static_cast<int>(std::floor((std::min(a[1], b[1]) - reach) / h)));
    const int y1 = std::min(map.height() - 1,
                            static_cast<int>(std::floor((std::max(a[1], b[1]) + reach) / h)));
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double len2 = ex * ex + ey * ey;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = (x + 0.5) * h - a[0], py = (y + 0.5) * h - a[1];
        const double t = len2 > 0.0 ? std::clamp((px * ex + py * ey) / len2, 0.0, 1.0) : 0.0;
        const double dx = px - t * ex, dy = py - t * ey;
        if (dx * dx + dy * dy > reach * reach) continue;
        if (map.at(x, y).depth_mm >= crack.depth_mm) continue;
        map.set(x, y, crack);
      }
    }
  }
}

}  // namespace impasto::cracks
