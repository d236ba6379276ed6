// The eyedropper's reading of the canvas (paint_probe.hpp): only the Canvas's public reads.
#include "impasto/paintcore/paint_probe.hpp"

#include <algorithm>
#include <cmath>

namespace impasto::paintcore {
namespace {

// Adds the pigments of the topmost dry layer holding paint at cell (x, y) to `pigment`;
// returns its paint height there (0: none holds paint).
float add_top_dry_paint(const Canvas& canvas, int x, int y, std::vector<double>& pigment) {
  const int index = canvas.tile_index(x / kTileSize, y / kTileSize);
  const std::size_t cell = static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize);
  const auto& layers = canvas.dry_layers();
  for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
    const DryTile* tile = layer->find(index);
    if (!tile || !(tile->volume_mm[cell] > kProbeBareBelowMm)) continue;
    for (std::size_t s = 0; s < pigment.size(); ++s)
      if (const float* amounts = tile->pigment(static_cast<int>(s))) pigment[s] += amounts[cell];
    return tile->volume_mm[cell];
  }
  return 0.0f;
}

}  // namespace

std::vector<double> PaintProbe::shares() const {
  double total = 0.0;
  for (double amount : pigment) total += amount;
  std::vector<double> result(pigment.size(), 0.0);
  if (!(total > 0.0)) return result;
  for (std::size_t s = 0; s < pigment.size(); ++s) result[s] = pigment[s] / total;
  return result;
}

PaintProbe probe_paint(const Painting& painting, double x_cells, double y_cells,
                       double radius_cells) {
  PaintProbe probe;
  probe.pigment.assign(static_cast<std::size_t>(painting.slot_count()), 0.0);
  if (!std::isfinite(x_cells) || !std::isfinite(y_cells) || !std::isfinite(radius_cells) ||
      radius_cells < 0.0) {
    return probe;
  }
  const Canvas& canvas = painting.canvas();
  // Cell (x, y) spans [x, x+1): its centre is x + 0.5.
  const double r = std::min(radius_cells, static_cast<double>(kMaxCanvasCells));
  const int x0 = std::max(0, static_cast<int>(std::floor(x_cells - r)));
  const int x1 = std::min(canvas.width_cells() - 1, static_cast<int>(std::floor(x_cells + r)));
  const int y0 = std::max(0, static_cast<int>(std::floor(y_cells - r)));
  const int y1 = std::min(canvas.height_cells() - 1, static_cast<int>(std::floor(y_cells + r)));
  // A disc smaller than a cell still takes the cell it lies in.
  const double r2 = std::max(r * r, 0.5);
  double wet_sum = 0.0, dry_sum = 0.0;
  // The visible paint's volume, its volume of medium, and that times its log10 RMS.
  double visible = 0.0, medium = 0.0, medium_log_rms = 0.0;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double dx = x + 0.5 - x_cells, dy = y + 0.5 - y_cells;
      if (dx * dx + dy * dy > r2) continue;
      ++probe.cells;
      const float wet = canvas.wet_volume_mm(x, y);
      wet_sum += wet;
      dry_sum += canvas.dry_height_mm(x, y);
      float seen = 0.0f;  // the height of the visible paint
      if (wet > kProbeBareBelowMm) {
        ++probe.wet_cells;
        seen = wet;
        for (std::size_t s = 0; s < probe.pigment.size(); ++s)
          probe.pigment[s] += canvas.pigment_mm(x, y, static_cast<int>(s));
      } else if ((seen = add_top_dry_paint(canvas, x, y, probe.pigment)) > 0.0f) {
        ++probe.dry_cells;
      }
      if (seen > 0.0f) {
        // The cell's surface medium is its top paint's, wet or dried.
        const Tile* tile = canvas.tile(canvas.tile_index(x / kTileSize, y / kTileSize));
        const PaintMedium there =
            cell_surface(tile, (y % kTileSize) * kTileSize + x % kTileSize).medium;
        visible += seen;
        medium += static_cast<double>(seen) * there.share;
        medium_log_rms += static_cast<double>(seen) * there.share * there.log_rms;
      }
    }
  }
  if (visible > 0.0 && medium > 0.0)
    probe.medium = {static_cast<float>(std::min(medium / visible, 1.0)),
                    static_cast<float>(medium_log_rms / medium)};
  if (probe.cells > 0) {
    probe.wet_mm = wet_sum / static_cast<double>(probe.cells);
    probe.dry_mm = dry_sum / static_cast<double>(probe.cells);
  }
  return probe;
}

}  // namespace impasto::paintcore
