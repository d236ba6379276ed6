#pragma once
// The brush: a head (its footprint, a height field in brush space) rasterised at the canvas
// cell size, and the brush's own paint grid (volume + pigment amounts per brush cell). Brush
// cells have the canvas cell area, so volume moves between brush and canvas cells 1:1.
#include <cstdint>
#include <string>
#include <vector>

#include "impasto/paintcore/brush_head.hpp"
#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/paint_surface.hpp"

namespace impasto::paintcore {

inline constexpr int kMaxBrushCells = 1024;  // cells across the brush grid

// A brush's width: (0, kMaxBrushSizeMm] wherever a size is taken (stroke files, paintings, the
// window's controls and presets), and no wider than a canvas's cells hold (kMaxBrushCells
// across; Brush refuses more, naming the cells).
inline constexpr double kMaxBrushSizeMm = 1000.0;
inline double max_brush_size_mm(double cell_mm) {
  const double by_cells = (kMaxBrushCells + 0.49) * cell_mm;  // rounds to kMaxBrushCells
  return by_cells < kMaxBrushSizeMm ? by_cells : kMaxBrushSizeMm;
}

// A load of paint: [0, kMaxLoadMm3] mm³ wherever a load is taken (stroke files, the engine),
// and no more than the head holds (Painting::load_brush refuses more, naming what fits).
inline constexpr double kMaxLoadMm3 = 1e9;

struct BrushSettings {
  std::string head = "round";  // head file name in the brushes folder (without .brush)
  double size_mm = 4.0;        // width of the head
  double stiffness = 0.5;      // 0 (soft, sinks deep) .. 1 (stiff, shallow contact)
};

// Throws std::runtime_error naming the field when settings are unusable.
void validate(const BrushSettings& settings);

class Brush {
 public:
  Brush() = default;  // no brush: covers nothing
  Brush(BrushHead head, BrushSettings settings, double cell_mm, int slot_count);

  bool empty() const { return cells_ == 0; }
  int cells_across() const { return cells_; }  // the grid is cells_across^2, row-major
  std::size_t cell_count() const { return static_cast<std::size_t>(cells_) * cells_; }
  const BrushHead& head() const { return head_; }
  // A head without bristles (the palette knife) is a rigid blade: it pushes paint at its
  // leading edge, steps a cell at a time and spreads its paint across all of it (Stepper).
  bool blade() const { return !(head_.bristles.spacing_mm > 0.0); }
  const BrushSettings& settings() const { return settings_; }

  // Height of the head's underside above its tip (mm) and whether the head covers a cell.
  const std::vector<float>& footprint_mm() const { return footprint_mm_; }
  const std::vector<std::uint8_t>& covers() const { return covers_; }
  float rim_mm() const { return rim_mm_; }  // the underside's highest point
  // The footprint and coverage (0 or 1) on a grid padded by one cell all round (the rim's
  // height and 0 there), (N + 2)^2 row-major: interpolation between cells needs no checks.
  const std::vector<float>& padded_footprint_mm() const { return padded_footprint_mm_; }
  const std::vector<float>& padded_coverage() const { return padded_coverage_; }
  // The same grids transposed (column-major): a canvas row crossing a head turned a quarter
  // walks them contiguously.
  const std::vector<float>& padded_footprint_mm_transposed() const {
    return padded_footprint_mm_t_;
  }
  const std::vector<float>& padded_coverage_transposed() const { return padded_coverage_t_; }
  std::size_t covered_cells() const { return covered_; }
  // The covered cells as runs of consecutive indices [begin, end), in index order: loops over
  // the paint grid visit them without testing every cell.
  struct CellRun {
    std::size_t begin, end;
  };
  const std::vector<CellRun>& covered_runs() const { return covered_runs_; }
  // The column of bristles each column of cells lies in (0 .. bristle_columns() - 1, in
  // order across u); a blade is one column. Paint in the brush flows along a bristle's hairs
  // and between the hairs of one bristle, not from bristle to bristle.
  const std::vector<std::uint32_t>& bristle_of_cell_column() const {
    return bristle_of_cell_column_;
  }
  std::size_t bristle_columns() const { return bristle_columns_; }
  // Penetration depth (mm) below the paint surface at pressure 1; softer heads sink deeper.
  double max_depth_mm() const;

  // The paint grid: height (mm) per cell and pigment amounts, slot-major.
  std::vector<float>& volume_mm() { return volume_mm_; }
  const std::vector<float>& volume_mm() const { return volume_mm_; }
  std::vector<float>& pigment_mm() { return pigment_mm_; }
  const std::vector<float>& pigment_mm() const { return pigment_mm_; }
  int slot_count() const {
    return cells_ ? static_cast<int>(pigment_mm_.size() / cell_count()) : 0;
  }
  void ensure_slots(int slot_count);

  // The body of the paint on the brush (the last paint loaded).
  PaintBody body() const { return body_; }
  void set_body(PaintBody body) { body_ = body; }
  // The medium of the paint on the brush (paint_surface.hpp), mixed as paint is loaded.
  const PaintMedium& medium() const { return medium_; }
  void set_medium(const PaintMedium& medium) { medium_ = medium; }

 private:
  BrushHead head_;
  BrushSettings settings_;
  int cells_ = 0;
  std::size_t covered_ = 0;
  std::vector<float> footprint_mm_;
  std::vector<std::uint8_t> covers_;
  std::vector<CellRun> covered_runs_;
  std::vector<std::uint32_t> bristle_of_cell_column_;
  std::size_t bristle_columns_ = 0;
  float rim_mm_ = 0.0f;
  std::vector<float> padded_footprint_mm_, padded_coverage_;
  std::vector<float> padded_footprint_mm_t_, padded_coverage_t_;
  std::vector<float> volume_mm_;
  std::vector<float> pigment_mm_;
  PaintBody body_ = kDefaultPaintBody;
  PaintMedium medium_;
};

}  // namespace impasto::paintcore
