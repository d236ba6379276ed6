#include "impasto/bench/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "impasto/util/statistics.hpp"

#include "impasto/paintcore/painting.hpp"

namespace impasto::bench {

using namespace impasto::paintcore;  // (this measures its parts)
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

// What the long-step benchmark compares: the canvas after its stroke, and the time it took.
struct LongStepRun {
  Painting painting;
  double seconds = 0;
  std::uint64_t steps = 0;  // the arc's
};

// Pen samples a brush's width apart: 4, as the window's mouse moves a 128-cell brush about
// 31 cells an event on a 4096-cell canvas fitted to the screen (docs/measurements/window.md,
// "Latency").
constexpr double kSamplesABrush = 4.0;

LongStepRun long_step_run(int brush_cells, double share, int threads, SimulationParams params) {
  constexpr double kLongStepDpi = 300.0;  // the window's canvases
  const double cell_mm = 25.4 / kLongStepDpi;
  const double n = brush_cells;
  LongStepRun run{Painting(CanvasSpec{5 * brush_cells, 3 * brush_cells, kLongStepDpi, 1}, threads)};
  Painting& painting = run.painting;
  params.long_step_share = 0.0;  // the band is the same under every run
  painting.set_params(params);
  painting.set_brush(BrushSettings{"round", n * cell_mm, 0.5});
  const double area_mm2 = std::numbers::pi * 0.25 * n * n * cell_mm * cell_mm;
  const auto draw = [&](const auto& at, int samples) {
    painting.begin_stroke();
    for (int i = 0; i <= samples; ++i) {
      PenSample s = sample_at(0.0, 0.0);
      const auto [x, y] = at(static_cast<double>(i) / samples);
      s.x_mm = x * cell_mm;
      s.y_mm = y * cell_mm;
      s.pressure = 0.7f;
      s.time_s = 0.008 * i;
      painting.stroke_to(s);
    }
    painting.end_stroke();
  };
  // A band of blue across the canvas, a fifth of it from the top edge's brush.
  painting.load_brush({{"ultramarine", 1.0}}, 0.5 * area_mm2);
  const auto band = [n](double t) { return std::array<double, 2>{(0.3 + 4.4 * t) * n, 1.2 * n}; };
  draw(band, static_cast<int>(std::ceil(4.4 * kSamplesABrush)));
  painting.wipe_brush();
  painting.load_brush({{"white", 1.0}}, 0.5 * area_mm2);
  params.long_step_share = share;
  painting.set_params(params);
  // An arc over the top of a circle through the band.
  constexpr double kFrom = std::numbers::pi + 0.35, kTo = 2.0 * std::numbers::pi - 0.35;
  const auto arc = [n](double t) {
    const double angle = kFrom + (kTo - kFrom) * t;
    return std::array<double, 2>{2.5 * n + 1.4 * n * std::cos(angle),
                                 2.5 * n + 1.4 * n * std::sin(angle)};
  };
  const std::uint64_t steps = painting.steps();
  const auto start = std::chrono::steady_clock::now();
  draw(arc, static_cast<int>(std::ceil(1.4 * (kTo - kFrom) * kSamplesABrush)));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.steps = painting.steps() - steps;
  return run;
}

}  // namespace

HeightDifference compare_wet_heights(const Canvas& a, const Canvas& reference) {
  if (a.width_cells() != reference.width_cells() || a.height_cells() != reference.height_cells())
    throw std::invalid_argument("compare_wet_heights: the canvases differ in size");
  const Canvas& b = reference;
  HeightDifference d;
  double height_sum = 0, error_sum = 0;
  std::size_t cells = 0;
  for (int y = 0; y < a.height_cells(); ++y)
    for (int x = 0; x < a.width_cells(); ++x) {
      const double ha = a.wet_volume_mm(x, y), hb = b.wet_volume_mm(x, y);
      if (ha <= 0.001 && hb <= 0.001) continue;
      ++cells;
      height_sum += hb;
      error_sum += std::abs(ha - hb);
      d.max_error_mm = std::max(d.max_error_mm, std::abs(ha - hb));
    }
  constexpr int kBlock = 4;
  double block_sum = 0;
  std::size_t blocks = 0;
  for (int by = 0; by + kBlock <= a.height_cells(); by += kBlock)
    for (int bx = 0; bx + kBlock <= a.width_cells(); bx += kBlock) {
      double ha = 0, hb = 0;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) {
          ha += a.wet_volume_mm(x, y);
          hb += b.wet_volume_mm(x, y);
        }
      ha /= kBlock * kBlock;
      hb /= kBlock * kBlock;
      if (ha <= 0.001 && hb <= 0.001) continue;
      ++blocks;
      block_sum += std::abs(ha - hb);
      d.max_block_error_mm = std::max(d.max_block_error_mm, std::abs(ha - hb));
    }
  d.mean_height_mm = cells ? height_sum / cells : 0.0;
  d.mean_error_mm = cells ? error_sum / cells : 0.0;
  d.mean_block_error_mm = blocks ? block_sum / blocks : 0.0;
  return d;
}

std::vector<LongStepResult> run_long_step_benchmark(int brush_cells,
                                                    const std::vector<double>& shares, int runs,
                                                    int threads, const SimulationParams& base) {
  if (brush_cells < 8 || brush_cells > kMaxBrushCells)
    throw std::runtime_error("bench steps: brush size must be 8.." +
                             std::to_string(kMaxBrushCells) + " cells, got " +
                             std::to_string(brush_cells));
  if (runs < 1) throw std::runtime_error("bench steps: runs must be >= 1");
  std::vector<double> all{0.0};
  all.insert(all.end(), shares.begin(), shares.end());
  std::vector<LongStepResult> results;
  std::optional<Painting> reference;
  for (const double share : all) {
    SimulationParams params = base;
    params.long_step_share = share;
    validate(params);
    std::vector<double> seconds;
    std::optional<LongStepRun> last;
    for (int r = 0; r < runs; ++r) {
      last.emplace(long_step_run(brush_cells, share, threads, base));
      seconds.push_back(last->seconds);
    }
    const Painting& painting = last->painting;
    LongStepResult result;
    result.brush_cells = brush_cells;
    result.share = share;
    result.step_cells = paintcore::max_step_cells(params, painting.brush().cells_across());
    result.steps = last->steps;
    result.seconds = util::median(seconds);
    const PaintTotals canvas = painting.canvas_totals(), brush = painting.brush_totals();
    result.volume_mm3 = painting.loaded_totals().volume - painting.wiped_totals().volume;
    result.volume_error_mm3 = canvas.volume + brush.volume - result.volume_mm3;
    const Canvas& a = painting.canvas();
    const Canvas& b = reference ? reference->canvas() : a;  // (the reference against itself)
    const int white = static_cast<int>(
        std::find(painting.pigment_slots().begin(), painting.pigment_slots().end(), "white") -
        painting.pigment_slots().begin());
    const HeightDifference heights = compare_wet_heights(a, b);
    result.mean_height_mm = heights.mean_height_mm;
    result.mean_height_error_mm = heights.mean_error_mm;
    result.max_height_error_mm = heights.max_error_mm;
    result.mean_block_error_mm = heights.mean_block_error_mm;
    result.max_block_error_mm = heights.max_block_error_mm;
    double white_sum = 0;
    std::size_t mixed = 0;
    for (int y = 0; y < a.height_cells(); ++y)
      for (int x = 0; x < a.width_cells(); ++x) {
        if (a.wet_volume_mm(x, y) < 0.01 || b.wet_volume_mm(x, y) < 0.01) continue;
        // White's share of the pigment (the rest is the band's blue).
        const auto share_of_white = [white](const Canvas& c, int cx, int cy) {
          double total = 0;
          for (int s = 0; s < 2; ++s) total += c.pigment_mm(cx, cy, s);
          return total > 0 ? c.pigment_mm(cx, cy, white) / total : 0.0;
        };
        const double d = std::abs(share_of_white(a, x, y) - share_of_white(b, x, y));
        ++mixed;
        white_sum += d;
        result.max_white_error = std::max(result.max_white_error, d);
      }
    result.mean_white_error = mixed ? white_sum / mixed : 0.0;
    results.push_back(result);
    if (!reference) reference.emplace(std::move(last->painting));
  }
  return results;
}

SimBenchmarkResult run_sim_benchmark(int brush_cells, int steps, int threads) {
  if (brush_cells < 1 || brush_cells > kMaxBrushCells)
    throw std::runtime_error("bench sim: brush size must be 1.." + std::to_string(kMaxBrushCells) +
                             " cells, got " + std::to_string(brush_cells));
  if (steps < 1) throw std::runtime_error("bench sim: steps must be >= 1");
  const double cell_mm = 25.4 / kDpi;
  const int canvas_cells = 3 * brush_cells + 64;
  Painting painting(CanvasSpec{canvas_cells, canvas_cells, kDpi, 1}, threads);
  // One-cell steps: a step is the unit this counts (a brush of 64 cells or more would take
  // long steps of several cells, docs/simulation.md, which bench steps measures).
  SimulationParams params;
  params.long_step_share = 0.0;
  painting.set_params(params);
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

}  // namespace impasto::bench
