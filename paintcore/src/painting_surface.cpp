// Media carried by the paint and varnish coats (paint_surface.hpp, docs/surface.md).
#include "painting_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "impasto/files/memory_budget.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {

void mix_brush_medium(Brush& brush, double before_mm3, double added_mm3,
                      const std::optional<Medium>& medium) {
  const PaintMedium loaded = medium ? paint_medium(*medium) : PaintMedium{};
  brush.set_medium(before_mm3 > 0.0 ? mix(brush.medium(), before_mm3, loaded, added_mm3) : loaded);
}

namespace {

constexpr int kLaidPlanes = 3;  // StrokeMedia: height laid, its medium, medium x log RMS

// The medium of the paint a stroke laid at cell `cell` of tile `index`, if it laid any.
std::optional<PaintMedium> laid_medium(const StrokeMedia& laid, int index, int cell) {
  const auto found = laid.find(index);
  if (found == laid.end()) return std::nullopt;
  const float* planes = found->second.data();
  const float height = planes[cell];
  if (!(height > 0.0f)) return std::nullopt;
  const float medium = planes[kTileCells + cell];
  return PaintMedium{std::min(medium / height, 1.0f),
                     medium > 0.0f ? planes[2 * kTileCells + cell] / medium : 0.0f};
}

bool any_medium(const Canvas& canvas) {
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (tile != nullptr && !tile->medium.empty()) return true;
  }
  return false;
}

}  // namespace

void exchange_medium(const Canvas& canvas, const UndoHistory& history, Brush& brush,
                     const Stepper& stepper, StrokeMedia& laid) {
  const PaintMedium on_brush_medium = brush.medium();
  // No medium on the brush nor anywhere on the canvas (none is in use): the brush takes none
  // up, the paint it lays carries none, and lay_stroke_medium has nothing to lay. Media change
  // only at a stroke's end, so skipping part of a stroke's exchanges loses nothing.
  if (on_brush_medium.share == 0.0f && !any_medium(canvas)) return;
  double picked = 0.0, medium = 0.0, medium_log_rms = 0.0;  // heights (mm): one cell's area
  int booked_index = -1;  // the tile last booked in `laid` (cells come row by row)
  std::vector<float>* booked = nullptr;
  stepper.for_each_exchange([&](int x, int y, float height_mm) {
    const int index = canvas.tile_index(x / kTileSize, y / kTileSize);
    const int cell = (y % kTileSize) * kTileSize + x % kTileSize;
    if (height_mm > 0.0f) {  // laid: the brush's medium as it was when it laid it
      if (index != booked_index) {
        booked = &laid[index];
        booked_index = index;
        if (booked->empty()) booked->assign(std::size_t{kLaidPlanes} * kTileCells, 0.0f);
      }
      std::vector<float>& planes = *booked;
      planes[static_cast<std::size_t>(cell)] += height_mm;
      const float share = height_mm * on_brush_medium.share;
      planes[static_cast<std::size_t>(kTileCells + cell)] += share;
      planes[static_cast<std::size_t>(2 * kTileCells + cell)] += share * on_brush_medium.log_rms;
      return;
    }
    const float taken = -height_mm;
    const Tile* tile = canvas.tile(index);
    // The cell held `had` before the stroke and `held` before the brush took its share now;
    // the part this stroke laid carries what the stroke laid there.
    const double held = (tile != nullptr ? tile->wet_volume_mm[cell] : 0.0f) + taken;
    double had = held;
    if (const std::optional<const Tile*> saved = history.saved_tile(index))
      had = *saved != nullptr ? (*saved)->wet_volume_mm[cell] : 0.0f;
    const double fresh = held > 0.0 ? std::clamp((held - had) / held, 0.0, 1.0) : 0.0;
    const PaintMedium there = mix(cell_surface(tile, cell).medium, 1.0 - fresh,
                                  laid_medium(laid, index, cell).value_or(on_brush_medium), fresh);
    picked += taken;
    medium += static_cast<double>(taken) * there.share;
    medium_log_rms += static_cast<double>(taken) * there.share * there.log_rms;
  });
  if (!(picked > 0.0) || (on_brush_medium.share == 0.0f && medium == 0.0)) return;
  const PaintMedium taken{static_cast<float>(medium / picked),
                          medium > 0.0 ? static_cast<float>(medium_log_rms / medium) : 0.0f};
  // What the brush holds now includes what it took (the same cell area throughout).
  double on_brush = 0.0;
  for (const float height : brush.volume_mm()) on_brush += height;
  brush.set_medium(mix(on_brush_medium, std::max(on_brush - picked, 0.0), taken, picked));
}

void lay_stroke_medium(Canvas& canvas, const UndoHistory& history, const PaintMedium& brush,
                       const std::vector<int>& tiles, StrokeMedia& laid) {
  for (const int index : tiles) {
    Tile* tile = canvas.tile_slot(index).get();
    if (tile == nullptr) continue;
    // Paint without a medium over cells that never had one or a varnish changes nothing: no
    // data is made.
    const auto laid_here = laid.find(index);
    const bool laid_a_medium =
        laid_here != laid.end() &&
        std::any_of(laid_here->second.begin() + kTileCells,
                    laid_here->second.begin() + 2 * kTileCells, [](float m) { return m > 0.0f; });
    const bool lays_medium = brush.share != 0.0f || laid_a_medium || !tile->medium.empty();
    if (!lays_medium && tile->varnish.empty()) continue;
    const std::optional<const Tile*> saved = history.saved_tile(index);
    if (!saved) continue;  // the stroke did not change this tile
    const Tile* before = *saved;
    if (lays_medium && tile->medium.empty()) {
      tile->medium.assign(static_cast<std::size_t>(kMediumPlanes) * kTileCells, 0.0f);
    }
    float* share = lays_medium ? tile->medium.data() : nullptr;
    float* log_rms = lays_medium ? share + kTileCells : nullptr;
    float* varnish = tile->varnish.empty() ? nullptr : tile->varnish.data();
    for (int c = 0; c < kTileCells; ++c) {
      const float had = before != nullptr ? before->wet_volume_mm[c] : 0.0f;
      const double gained = static_cast<double>(tile->wet_volume_mm[c]) - had;
      if (!(gained > 0.0)) continue;  // paint taken or moved away leaves the surface's finish
      // More than a film of paint over a varnish buries it: the paint's surface is on top.
      if (varnish != nullptr && gained > kSurfaceFilmMm) {
        for (int plane = 0; plane < kVarnishPlanes; ++plane) varnish[plane * kTileCells + c] = 0.0f;
      }
      if (!lays_medium) continue;
      // The surface there: the wet paint, over at most a film's depth of dry paint (none on
      // the bare ground, where the first paint makes the surface).
      const double under = had + std::min<double>(kSurfaceFilmMm, tile->dry_height_mm[c]);
      const PaintMedium mixed =
          mix({share[c], log_rms[c]}, under, laid_medium(laid, index, c).value_or(brush), gained);
      share[c] = mixed.share;
      log_rms[c] = mixed.log_rms;
    }
  }
  laid.clear();
}

void dry_varnish(Canvas& canvas, UndoHistory& history, float fraction) {
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (tile == nullptr || tile->varnish.empty()) continue;
    const float* wet = varnish_plane(*tile, 1);
    if (std::none_of(wet, wet + kTileCells, [](float v) { return v != 0.0f; })) continue;
    history.before_tile_change(index, tile);
    canvas.mark_dirty(index);
    float* drying = canvas.tile_slot(index)->varnish.data() + kTileCells;
    for (int c = 0; c < kTileCells; ++c) drying[c] -= drying[c] * fraction;
  }
}

namespace {

// The coat each cell of `r` (row-major) takes: the thickness, levelled toward the mean of the
// surface under it within kVarnishLevellingMm (over the coat's own cells: the varnish flows
// only where it lies), at least the wetting film, and as much varnish in all as an even coat.
std::vector<float> levelled_coat(const Canvas& canvas, const CellRect& r, double thickness_mm) {
  const int w = r.x1 - r.x0, h = r.y1 - r.y0;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  files::check_allocation("apply_varnish", "the coat's levelling", 12ull * n);
  std::vector<float> height(n), across(n), coat(n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) height[at(x, y)] = surface_height_mm(canvas, r.x0 + x, r.y0 + y);
  const int reach =
      std::max(1, static_cast<int>(std::lround(kVarnishLevellingMm / canvas.cell_mm())));
  // Box sums by prefix sums (double), along the rows, then down the columns.
  std::vector<double> prefix(static_cast<std::size_t>(std::max(w, h)) + 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) prefix[x + 1] = prefix[x] + height[at(x, y)];
    for (int x = 0; x < w; ++x)
      across[at(x, y)] =
          static_cast<float>(prefix[std::min(x + reach + 1, w)] - prefix[std::max(x - reach, 0)]);
  }
  const double share = varnish_levelled_share(thickness_mm);
  double total = 0.0;
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) prefix[y + 1] = prefix[y] + across[at(x, y)];
    const int nx = std::min(x + reach + 1, w) - std::max(x - reach, 0);
    for (int y = 0; y < h; ++y) {
      const int y0 = std::max(y - reach, 0), y1 = std::min(y + reach + 1, h);
      const double mean = (prefix[y1] - prefix[y0]) / (static_cast<double>(nx) * (y1 - y0));
      const double here = height[at(x, y)];
      const double c =
          std::max(thickness_mm + share * (mean - here), kVarnishWettingShare * thickness_mm);
      coat[at(x, y)] = static_cast<float>(c);
      total += c;
    }
  }
  // What the peaks could not give (they keep their wetting film) comes off the rest evenly.
  const double scale = total > 0.0 ? thickness_mm * static_cast<double>(n) / total : 1.0;
  if (scale != 1.0)
    for (float& c : coat) c = static_cast<float>(c * scale);
  return coat;
}

}  // namespace

void Painting::apply_varnish(Finish finish, double thickness_mm, std::optional<CellRect> region) {
  Impl& p = *impl_;
  if (static_cast<int>(finish) >= kFinishCount)
    throw std::runtime_error("apply_varnish: field 'finish' is not a finish");
  if (!(thickness_mm >= kMinVarnishMm && thickness_mm <= kMaxVarnishMm))
    throw std::runtime_error("apply_varnish: field 'thickness_mm' must be in [" +
                             std::to_string(kMinVarnishMm) + ", " + std::to_string(kMaxVarnishMm) +
                             "], got " + std::to_string(thickness_mm));
  const CellRect whole{0, 0, p.canvas.width_cells(), p.canvas.height_cells()};
  CellRect r = region.value_or(whole);
  if (region) {
    r = {std::max(r.x0, 0), std::max(r.y0, 0), std::min(r.x1, whole.x1), std::min(r.y1, whole.y1)};
    if (r.empty())
      throw std::runtime_error("apply_varnish: field 'region' (" + std::to_string(region->x0) +
                               "," + std::to_string(region->y0) + " to " +
                               std::to_string(region->x1) + "," + std::to_string(region->y1) +
                               ") covers no cell of the " + std::to_string(whole.x1) + "x" +
                               std::to_string(whole.y1) + " canvas");
  }
  end_stroke();
  p.history.begin(p.brush, p.ledger, p.slots, p.canvas.dry_layers().size(), p.canvas.tile_count());
  const std::vector<float> coat = levelled_coat(p.canvas, r, thickness_mm);
  const auto rough = static_cast<float>(finish_log_rms(finish));
  for (int ty = r.y0 / kTileSize; ty <= (r.y1 - 1) / kTileSize; ++ty) {
    for (int tx = r.x0 / kTileSize; tx <= (r.x1 - 1) / kTileSize; ++tx) {
      const int index = p.canvas.tile_index(tx, ty);
      p.history.before_tile_change(index, p.canvas.tile(index));
      Tile& tile = p.canvas.ensure_tile(index, slot_count());
      if (tile.varnish.empty())
        tile.varnish.assign(static_cast<std::size_t>(kVarnishPlanes) * kTileCells, 0.0f);
      float* thickness = tile.varnish.data();
      float* wet = thickness + kTileCells;
      float* log_rms = wet + kTileCells;
      const CellRect cells{std::max(r.x0 - tx * kTileSize, 0), std::max(r.y0 - ty * kTileSize, 0),
                           std::min(r.x1 - tx * kTileSize, kTileSize),
                           std::min(r.y1 - ty * kTileSize, kTileSize)};
      for (int y = cells.y0; y < cells.y1; ++y) {
        for (int x = cells.x0; x < cells.x1; ++x) {
          const int c = y * kTileSize + x;
          const float here = coat[static_cast<std::size_t>(ty * kTileSize + y - r.y0) *
                                      static_cast<std::size_t>(r.x1 - r.x0) +
                                  static_cast<std::size_t>(tx * kTileSize + x - r.x0)];
          thickness[c] += here;
          wet[c] += here;
          log_rms[c] = rough;
        }
      }
      p.canvas.mark_dirty(index, {tx * kTileSize + cells.x0, ty * kTileSize + cells.y0,
                                  tx * kTileSize + cells.x1, ty * kTileSize + cells.y1});
    }
  }
  p.history.commit();
}

}  // namespace impasto::paintcore
