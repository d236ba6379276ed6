#include "impasto/paintcore/brush.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impasto::paintcore {

void validate(const BrushSettings& settings) {
  if (!(settings.size_mm > 0.0 && settings.size_mm <= kMaxBrushSizeMm))
    throw std::runtime_error("brush settings: field 'size_mm' must be in (0, 1000] mm, got " +
                             std::to_string(settings.size_mm));
  if (!std::isfinite(settings.stiffness) || settings.stiffness < 0.0 || settings.stiffness > 1.0)
    throw std::runtime_error("brush settings: field 'stiffness' must be in [0, 1], got " +
                             std::to_string(settings.stiffness));
}

Brush::Brush(BrushHead head, BrushSettings settings, double cell_mm, int slot_count)
    : head_(std::move(head)), settings_(std::move(settings)) {
  validate(settings_);
  const double across = std::round(settings_.size_mm / cell_mm);
  if (across > kMaxBrushCells)
    throw std::runtime_error(
        "brush settings: field 'size_mm' " + std::to_string(settings_.size_mm) + " mm is " +
        std::to_string(static_cast<long long>(across)) + " cells at this DPI; at most " +
        std::to_string(kMaxBrushCells) + " are allowed");
  cells_ = std::max(1, static_cast<int>(across));
  const double half_size_mm = 0.5 * settings_.size_mm;
  // Bristle relief never exceeds a tenth of the half width: a hair-fine head has no furrows
  // deeper than itself.
  const double bristle_depth = head_.bristles.depth_mm * (1.0 + head_.bristles.jitter);
  double bristle_scale =
      bristle_depth > 0.0 ? std::min(1.0, 0.1 * half_size_mm / bristle_depth) : 1.0;
  // Nor do bristles finer than the grid can show: their relief fades from 4 cells a column
  // down to 2 (the Nyquist limit). Nearer the limit what a cell shows of them depends on
  // where the stroke lies on the grid: kept whole down to 2.5 cells, a 6 mm round's stroke at
  // 150 dpi (2.66 cells a column) shaded 1.6 ΔE2000 apart half a cell up or down.
  const double columns_cells = head_.bristles.spacing_mm / cell_mm;
  bristle_scale *= std::clamp((columns_cells - 2.0) / 2.0, 0.0, 1.0);
  footprint_mm_.assign(cell_count(), 0.0f);
  covers_.assign(cell_count(), 0);
  for (int j = 0; j < cells_; ++j)
    for (int i = 0; i < cells_; ++i) {
      // Cell centre in brush space, u and v in [-1, 1].
      const double u = (i + 0.5) / cells_ * 2.0 - 1.0;
      const double v = (j + 0.5) / cells_ * 2.0 - 1.0;
      const std::size_t k = static_cast<std::size_t>(j) * cells_ + i;
      // A one-cell brush covers its only cell whatever the shape.
      covers_[k] = cells_ == 1 || head_.covers(u, v);
      footprint_mm_[k] =
          static_cast<float>(head_.height(u, v) * half_size_mm +
                             bristle_scale * head_.bristle_height_mm(u * half_size_mm));
      covered_ += covers_[k];
    }
  if (covered_ == 0) {  // a thin head on a coarse grid: its centre cell still holds paint
    covers_[static_cast<std::size_t>(cells_ / 2) * cells_ + cells_ / 2] = 1;
    covered_ = 1;
  }
  for (std::size_t k = 0; k < covers_.size(); ++k) {
    if (!covers_[k]) continue;
    if (covered_runs_.empty() || covered_runs_.back().end != k) covered_runs_.push_back({k, k});
    covered_runs_.back().end = k + 1;
  }
  bristle_of_cell_column_.assign(static_cast<std::size_t>(cells_), 0);
  const auto bristle_at = [&](int i) {
    return head_.bristle_column(((i + 0.5) / cells_ * 2.0 - 1.0) * half_size_mm);
  };
  for (int i = 0; i < cells_; ++i)
    bristle_of_cell_column_[static_cast<std::size_t>(i)] =
        static_cast<std::uint32_t>(bristle_at(i) - bristle_at(0));
  bristle_columns_ = static_cast<std::size_t>(bristle_of_cell_column_.back()) + 1;
  rim_mm_ = *std::max_element(footprint_mm_.begin(), footprint_mm_.end());
  const auto padded = static_cast<std::size_t>(cells_ + 2);
  padded_footprint_mm_.assign(padded * padded, rim_mm_);
  padded_coverage_.assign(padded * padded, 0.0f);
  for (int j = 0; j < cells_; ++j)
    for (int i = 0; i < cells_; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * cells_ + i;
      const std::size_t p =
          static_cast<std::size_t>(j + 1) * padded + static_cast<std::size_t>(i + 1);
      padded_footprint_mm_[p] = footprint_mm_[k];
      padded_coverage_[p] = covers_[k] ? 1.0f : 0.0f;
    }
  padded_footprint_mm_t_.resize(padded * padded);
  padded_coverage_t_.resize(padded * padded);
  for (std::size_t j = 0; j < padded; ++j)
    for (std::size_t i = 0; i < padded; ++i) {
      padded_footprint_mm_t_[i * padded + j] = padded_footprint_mm_[j * padded + i];
      padded_coverage_t_[i * padded + j] = padded_coverage_[j * padded + i];
    }
  volume_mm_.assign(cell_count(), 0.0f);
  ensure_slots(slot_count);
}

double Brush::max_depth_mm() const {
  return head_.rise * 0.5 * settings_.size_mm * (1.25 - 0.75 * settings_.stiffness);
}

void Brush::ensure_slots(int slot_count) {
  if (cells_ && this->slot_count() < slot_count)
    pigment_mm_.resize(static_cast<std::size_t>(slot_count) * cell_count(), 0.0f);
}

}  // namespace impasto::paintcore
