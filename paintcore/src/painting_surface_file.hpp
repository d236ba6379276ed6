#pragma once
// The painting file's surface section (version 6, docs/painting-format.md): the media and
// varnish of the tiles that have them (paint_surface.hpp) and the medium of the paint on the
// brush, at the end of the payload.
#include <string>

#include "painting_file_io.hpp"

namespace impasto::paintcore::file_io {

inline constexpr std::uint32_t kSurfaceVersion = 6;  // the first version with the section
inline constexpr std::uint8_t kSurfaceHasMedium = 1;
inline constexpr std::uint8_t kSurfaceHasVarnish = 2;

// Which planes a tile holds (kSurfaceHas*).
inline std::uint8_t surface_planes(const Tile& tile) {
  return static_cast<std::uint8_t>((tile.medium.empty() ? 0 : kSurfaceHasMedium) |
                                   (tile.varnish.empty() ? 0 : kSurfaceHasVarnish));
}

template <typename W>
void write_surface_planes(W& w, const Tile& tile) {
  if (!tile.medium.empty()) w.put_floats(tile.medium.data(), tile.medium.size());
  if (!tile.varnish.empty()) w.put_floats(tile.varnish.data(), tile.varnish.size());
}

// The undo history's tiles carry the same planes, flagged in the two high bits of their slot
// count byte (at most 16 slots: bits 5 to 7 were always zero before version 6).
inline constexpr int kHistorySurfaceShift = 6;

template <typename W>
void write_brush_medium(W& w, const Brush& brush) {
  w.put(brush.medium().share);
  w.put(brush.medium().log_rms);
}

// Reads what write_brush_medium wrote, checked.
inline void read_brush_medium(Reader& r, Brush& brush, const std::string& field) {
  const auto lo = static_cast<float>(kMinLogRms), hi = static_cast<float>(kMaxLogRms);
  PaintMedium medium;
  medium.share = r.get<float>(field + ".share");
  medium.log_rms = r.get<float>(field + ".log_rms");
  if (!(medium.share >= 0.0f && medium.share <= 1.0f))
    r.fail(field + ".share", "must be in [0, 1]");
  if (!(medium.log_rms >= lo && medium.log_rms <= hi))
    r.fail(field + ".log_rms",
           "is outside [" + std::to_string(kMinLogRms) + ", " + std::to_string(kMaxLogRms) + "]");
  brush.set_medium(medium);
}

template <typename W>
void write_surfaces(W& w, const Canvas& canvas, const Brush& brush) {
  std::uint32_t count = 0;
  for (int index = 0; index < canvas.tile_count(); ++index)
    if (has_surface(canvas.tile(index))) ++count;
  w.put(count);
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!has_surface(tile)) continue;
    w.put(static_cast<std::uint32_t>(index));
    w.put(surface_planes(*tile));
    write_surface_planes(w, *tile);
  }
  write_brush_medium(w, brush);
}

// Floats of one plane, each finite and in [lo, hi].
inline void read_plane(Reader& r, float* out, float lo, float hi, const std::string& field) {
  for (int c = 0; c < kTileCells; ++c) {
    const auto v = r.get<float>(field);
    if (!(v >= lo && v <= hi))  // NaN fails too
      r.fail(field, "cell " + std::to_string(c) + " (" + std::to_string(v) + ") is outside [" +
                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out[c] = v;
  }
}

inline void read_surface_planes(Reader& r, Tile& tile, std::uint8_t planes,
                                const std::string& field) {
  const auto lo = static_cast<float>(kMinLogRms), hi = static_cast<float>(kMaxLogRms);
  if ((planes & ~(kSurfaceHasMedium | kSurfaceHasVarnish)) != 0)
    r.fail(field + ".planes", "unknown planes " + std::to_string(planes));
  if (planes & kSurfaceHasMedium) {
    tile.medium.assign(static_cast<std::size_t>(kMediumPlanes) * kTileCells, 0.0f);
    read_plane(r, tile.medium.data(), 0.0f, 1.0f, field + ".medium.share");
    read_plane(r, tile.medium.data() + kTileCells, lo, hi, field + ".medium.log_rms");
  }
  if (planes & kSurfaceHasVarnish) {
    tile.varnish.assign(static_cast<std::size_t>(kVarnishPlanes) * kTileCells, 0.0f);
    float* thickness = tile.varnish.data();
    r.get_amounts(thickness, kTileCells, field + ".varnish.thickness");
    float* wet = thickness + kTileCells;
    r.get_amounts(wet, kTileCells, field + ".varnish.wet");
    for (int c = 0; c < kTileCells; ++c)
      if (wet[c] > thickness[c])
        r.fail(field + ".varnish.wet", "cell " + std::to_string(c) + " is wetter than thick");
    read_plane(r, wet + kTileCells, lo, hi, field + ".varnish.log_rms");
  }
}

inline void read_surfaces(Reader& r, Canvas& canvas, Brush& brush) {
  const int tile_count = canvas.tile_count();
  const auto count = r.get_count("surfaces.count", static_cast<std::uint32_t>(tile_count),
                                 5 + kMediumPlanes * kTileCells * sizeof(float));
  int previous = -1;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::string field = "surfaces[" + std::to_string(k) + "]";
    const auto index =
        static_cast<int>(r.get_count(field + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (index <= previous) r.fail(field + ".index", "tiles are not in ascending order");
    previous = index;
    Tile* tile = canvas.tile_slot(index).get();
    if (tile == nullptr) r.fail(field + ".index", "names a tile the painting does not hold");
    const auto planes = r.get<std::uint8_t>(field + ".planes");
    if (planes == 0) r.fail(field + ".planes", "no planes");
    read_surface_planes(r, *tile, planes, field);
  }
  read_brush_medium(r, brush, "brush.medium");
}

}  // namespace impasto::paintcore::file_io
