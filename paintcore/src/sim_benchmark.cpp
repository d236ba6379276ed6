#include "impasto/paintcore/sim_benchmark.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {
namespace {

constexpr double kDpi = 254.0;  // 0.1 mm cells

PenSample sample_at(double x_mm, double y_mm) {
  PenSample s;
  s.x_mm = x_mm;
  s.y_mm = y_mm;
  s.pressure = 1.0f;
  s.buttons = kPenTip;
  return s;
}

}  // namespace

SimBenchmarkResult run_sim_benchmark(int brush_cells, int steps, int threads) {
  if (brush_cells < 1 || brush_cells > kMaxBrushCells)
    throw std::runtime_error("bench sim: brush size must be 1.." + std::to_string(kMaxBrushCells) +
                             " cells, got " + std::to_string(brush_cells));
  if (steps < 1) throw std::runtime_error("bench sim: steps must be >= 1");
  const double cell_mm = 25.4 / kDpi;
  const int canvas_cells = 3 * brush_cells + 64;
  Painting painting(CanvasSpec{canvas_cells, canvas_cells, kDpi, 1}, threads);
  painting.set_brush(BrushSettings{"round", brush_cells * cell_mm, 0.2});
  const double brush_area_mm2 = brush_cells * brush_cells * cell_mm * cell_mm;
  painting.load_brush({{"white", 3.0}, {"ultramarine", 1.0}}, 0.5 * brush_area_mm2);
  painting.set_undo_budget_bytes(std::size_t{256} << 20);

  // Back and forth along the middle row, one cell per sample (and so per step).
  const double y_mm = 0.5 * canvas_cells * cell_mm;
  const double left = (brush_cells * 0.5 + 2) * cell_mm;
  const int span = canvas_cells - brush_cells - 4;
  int position = 0, direction = 1;
  const auto advance = [&] {
    if (position + direction < 0 || position + direction > span) direction = -direction;
    position += direction;
    painting.stroke_to(sample_at(left + position * cell_mm, y_mm));
  };
  painting.begin_stroke();
  for (int i = 0; i < 20; ++i) advance();  // warm-up: paint on the canvas, caches filled
  const std::uint64_t steps0 = painting.steps();
  const std::uint64_t cells0 = painting.cells_updated();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) advance();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  painting.end_stroke();

  SimBenchmarkResult r;
  r.brush_cells = brush_cells;
  r.steps = painting.steps() - steps0;
  r.seconds = seconds;
  const double brush = static_cast<double>(brush_cells) * brush_cells;
  r.cells_per_second = brush * static_cast<double>(r.steps) / seconds;
  r.window_cells_per_second = static_cast<double>(painting.cells_updated() - cells0) / seconds;
  r.steps_per_second = static_cast<double>(r.steps) / seconds;
  return r;
}

}  // namespace impasto::paintcore
