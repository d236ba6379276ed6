#include "impasto/bench/marks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace impasto::bench {

using namespace impasto::paintcore;  // (this measures its parts)
namespace {

// The sampling trace is what varies faster than this along the stroke (a hand's own
// unevenness is slower).
constexpr double kTraceSmoothingMm = 3.0;
// A sampling trace's peak counts against a floor no lower than a ripple of this share of the
// film (0.3 um in a 0.6 mm film).
constexpr double kTraceFloorShare = 5e-4;

// Mean thickness (wet + dry) across the stroke, row by row, over its middle third along x.
std::vector<double> mean_profile_across(const Canvas& c, int x0, int x1) {
  std::vector<double> across;
  for (int y = 0; y < c.height_cells(); ++y) {
    double sum = 0.0;
    for (int x = x0; x < x1; ++x) sum += c.wet_volume_mm(x, y) + c.dry_height_mm(x, y);
    across.push_back(sum / (x1 - x0));
  }
  return across;
}

// The dominant period (in cells) of `band` less its mean, from its discrete Fourier transform.
double dominant_period_cells(const std::vector<double>& band) {
  if (band.size() < 6) return 0.0;
  double mean = 0.0;
  for (double v : band) mean += v / static_cast<double>(band.size());
  const auto n = static_cast<double>(band.size());
  double best_power = 0.0, best_period = 0.0;
  for (int k = 2; k < static_cast<int>(band.size()) / 2; ++k) {
    std::complex<double> sum;
    for (std::size_t i = 0; i < band.size(); ++i)
      sum += (band[i] - mean) *
             std::polar(1.0, -2.0 * std::numbers::pi * k * static_cast<double>(i) / n);
    if (std::norm(sum) > best_power) best_power = std::norm(sum), best_period = n / k;
  }
  return best_period;
}

// The painted band of a profile across a stroke: [begin, end) of the values above 1 um.
struct PaintedBand {
  std::size_t begin = 0, end = 0;
  std::size_t width() const { return end - begin; }
};
PaintedBand painted_band(const std::vector<double>& across) {
  const auto painted = [](double v) { return v > 1e-3; };
  const auto first = std::find_if(across.begin(), across.end(), painted);
  if (first == across.end()) return {};
  const auto last = std::find_if(across.rbegin(), across.rend(), painted);
  return {static_cast<std::size_t>(first - across.begin()),
          across.size() - static_cast<std::size_t>(last - across.rbegin())};
}

// Furrows: the period (cells) of the profile over the band's middle three fifths.
double furrow_period_cells(const std::vector<double>& across, PaintedBand band) {
  const std::size_t fifth = band.width() / 5;
  return dominant_period_cells(
      std::vector<double>(across.begin() + static_cast<std::ptrdiff_t>(band.begin + fifth),
                          across.begin() + static_cast<std::ptrdiff_t>(band.end - fifth)));
}

// The mean of `values` over a box `width` cells wide centred on cell i (its end cells count
// in part; beyond the ends the end values stand in).
double box_mean(const std::vector<double>& values, std::ptrdiff_t i, double width) {
  const double half = 0.5 * width;
  const auto reach = static_cast<std::ptrdiff_t>(std::ceil(half - 0.5));
  const auto size = static_cast<std::ptrdiff_t>(values.size());
  double sum = 0.0, weight = 0.0;
  for (std::ptrdiff_t k = -reach; k <= reach; ++k) {
    // The share of cell i + k inside [i - half, i + half].
    const double w = std::clamp(half + 0.5 - static_cast<double>(std::abs(k)), 0.0, 1.0);
    const std::ptrdiff_t j = std::clamp<std::ptrdiff_t>(i + k, 0, size - 1);
    sum += w * values[static_cast<std::size_t>(j)];
    weight += w;
  }
  return sum / weight;
}

// Furrows' depth: the RMS of the profile's middle three fifths less its running mean over one
// period (cells, fractional), which leaves what varies at the bristles' spacing and removes
// the mark's broad shape.
double furrow_rms(const std::vector<double>& across, PaintedBand band, double period_cells) {
  const std::size_t fifth = band.width() / 5;
  const auto lo = static_cast<std::ptrdiff_t>(band.begin + fifth);
  const auto hi = static_cast<std::ptrdiff_t>(band.end - fifth);
  if (hi <= lo || period_cells < 1.0) return 0.0;
  double sum_squares = 0.0;
  for (std::ptrdiff_t i = lo; i < hi; ++i) {
    const double d = across[static_cast<std::size_t>(i)] - box_mean(across, i, period_cells);
    sum_squares += d * d;
  }
  return std::sqrt(sum_squares / static_cast<double>(hi - lo));
}

// Mean thickness (wet + dry) along the stroke, column by column, over rows [y0, y1).
std::vector<double> mean_profile_along(const Canvas& c, int y0, int y1) {
  std::vector<double> along;
  for (int x = 0; x < c.width_cells(); ++x) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y) sum += c.wet_volume_mm(x, y) + c.dry_height_mm(x, y);
    along.push_back(sum / (y1 - y0));
  }
  return along;
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

double furrow_rms_mm(const Canvas& canvas, int x0, int x1, double period_mm) {
  const std::vector<double> across = mean_profile_across(canvas, x0, x1);
  return furrow_rms(across, painted_band(across), period_mm / canvas.cell_mm());
}

double furrow_period_mm(const Canvas& canvas, int x0, int x1) {
  const std::vector<double> across = mean_profile_across(canvas, x0, x1);
  return furrow_period_cells(across, painted_band(across)) * canvas.cell_mm();
}

SamplingTrace sampling_trace(const std::vector<double>& along, double cell_mm, double period_mm,
                             double smooth_mm, double film_mm) {
  SamplingTrace trace;
  const std::size_t n = along.size();
  if (n < 8 || !(film_mm > 0.0)) return trace;
  std::vector<double> residual(n);
  double sum_squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    residual[i] = along[i] - box_mean(along, static_cast<std::ptrdiff_t>(i), smooth_mm / cell_mm);
    sum_squares += residual[i] * residual[i];
  }
  trace.rms_share = std::sqrt(sum_squares / static_cast<double>(n)) / film_mm;
  const double period_cells = period_mm / cell_mm;
  const double event_bin = static_cast<double>(n) / period_cells;
  const auto nyquist = static_cast<long>(n / 2);
  if (period_cells < 3.0 || event_bin < 4.0) return trace;
  const auto power = [&](long k) {
    std::complex<double> sum;
    for (std::size_t i = 0; i < n; ++i)
      sum += residual[i] * std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(k) *
                                               static_cast<double>(i) / static_cast<double>(n));
    return std::norm(sum);
  };
  const auto centre = std::lround(event_bin);
  double peak = 0.0;
  for (long k = centre - 1; k <= centre + 1; ++k)
    if (k >= 1 && k <= nyquist) peak = std::max(peak, power(k));
  std::vector<double> around;
  const long from = std::max(1L, std::lround(0.5 * event_bin));
  const long to = std::min(nyquist, std::lround(2.0 * event_bin));
  for (long k = from; k <= to; ++k)
    if (std::abs(k - centre) > 2) around.push_back(power(k));
  // The peak's amplitude (a sinusoid's, over the film); the floor no lower than the power of
  // a sinusoid of kTraceFloorShare of the film: a smooth stroke on a flat canvas has next to
  // no texture of its own, and a ratio to nothing would count a ripple far below what the
  // height map or a raking light resolves.
  const double amplitude = 2.0 * std::sqrt(peak) / static_cast<double>(n);
  trace.peak_share = amplitude / film_mm;
  const double least = std::pow(0.5 * kTraceFloorShare * film_mm * static_cast<double>(n), 2.0);
  const double floor = std::max(median_of(around), least);
  trace.peak = peak / floor;
  return trace;
}

double ridge_prominence(const std::vector<double>& along, std::size_t begin, std::size_t end,
                        std::size_t reach) {
  double most = 0.0;
  end = std::min(end, along.size());
  for (std::size_t i = begin; i < end; ++i) {
    double left = along[i], right = along[i];
    for (std::size_t k = 1; k <= reach; ++k) {
      if (i >= k) left = std::min(left, along[i - k]);
      if (i + k < along.size()) right = std::min(right, along[i + k]);
    }
    most = std::max(most, along[i] - std::max(left, right));
  }
  return most;
}

MarkFigures measure_mark(const std::string& head_name, PaintBody body, const MarkStroke& stroke) {
  const double cell_mm = 25.4 / stroke.dpi;
  const double margin_mm = 1.5 * stroke.size_mm;
  const CanvasSpec spec{static_cast<int>(std::lround((stroke.length_mm + 2 * margin_mm) / cell_mm)),
                        static_cast<int>(std::lround(3.0 * stroke.size_mm / cell_mm)), stroke.dpi,
                        0};
  Painting painting(spec, stroke.threads);
  painting.set_params(stroke.params);
  painting.set_brush(BrushSettings{head_name, stroke.size_mm, 0.5});
  const Brush& brush = painting.brush();
  MarkFigures f;
  f.head = head_name;
  f.body = body;
  f.size_mm = stroke.size_mm;
  f.dpi = stroke.dpi;
  f.spacing_mm = stroke.spacing_mm;
  f.load_mm3 = stroke.load_mm3_at_8mm * (stroke.size_mm / 8.0) * (stroke.size_mm / 8.0);
  painting.load_brush({{"white", 1.0}}, f.load_mm3, body);

  const double y = 1.5 * stroke.size_mm;
  const auto samples = std::max<long>(1, std::lround(stroke.length_mm / stroke.spacing_mm));
  const auto start = std::chrono::steady_clock::now();
  painting.begin_stroke();
  for (long i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(samples);
    PenSample s;
    s.time_s = stroke.seconds * t;
    s.x_mm = margin_mm + stroke.length_mm * t;
    s.y_mm = y;
    s.pressure = stroke.pressure;
    s.buttons = kPenTip | kPenInRange;
    painting.stroke_to(s);
  }
  painting.end_stroke();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  f.steps = painting.steps();
  f.seconds_per_step = f.steps ? seconds / static_cast<double>(f.steps) : 0.0;
  f.deposited_share = painting.canvas_totals().volume / painting.loaded_totals().volume;
  f.thickness = painting.paint_thickness();

  // Across the stroke's middle third: width, edge ridges, furrows.
  const Canvas& c = painting.canvas();
  const int x0 = static_cast<int>((margin_mm + stroke.length_mm / 3) / cell_mm);
  const int x1 = static_cast<int>((margin_mm + 2 * stroke.length_mm / 3) / cell_mm);
  const std::vector<double> across = mean_profile_across(c, x0, x1);
  const PaintedBand band = painted_band(across);
  if (band.width() == 0) return f;
  const std::size_t begin = band.begin, end = band.end;
  f.width_mm = static_cast<double>(band.width()) * cell_mm;
  const std::size_t third = band.width() / 3;
  std::vector<double> middle(across.begin() + static_cast<std::ptrdiff_t>(begin + third),
                             across.begin() + static_cast<std::ptrdiff_t>(end - third));
  std::nth_element(middle.begin(), middle.begin() + static_cast<std::ptrdiff_t>(middle.size() / 2),
                   middle.end());
  const double middle_median = middle.empty() ? 0.0 : middle[middle.size() / 2];
  const double edge_crest =
      std::max(*std::max_element(across.begin() + static_cast<std::ptrdiff_t>(begin),
                                 across.begin() + static_cast<std::ptrdiff_t>(begin + third)),
               *std::max_element(across.begin() + static_cast<std::ptrdiff_t>(end - third),
                                 across.begin() + static_cast<std::ptrdiff_t>(end)));
  f.edge_ridge_mm = edge_crest - middle_median;
  f.furrow_period_mm = furrow_period_cells(across, band) * cell_mm;
  f.bristle_spacing_mm =
      brush.head().bristles.spacing_mm * (1.0 + brush.head().splay * stroke.pressure);
  f.middle_mm = middle_median;
  f.furrow_rms_mm = furrow_rms(across, band, f.bristle_spacing_mm / cell_mm);

  // Along the stroke's middle third (rows), away from where it starts and lifts: the pen's
  // sampling left in it. Then the end: a rim where the brush lifted.
  const std::vector<double> along =
      mean_profile_along(c, static_cast<int>(begin + third),
                         static_cast<int>(std::max(end - third, begin + third + 1)));
  const auto column = [&](double x_mm) {
    return static_cast<std::size_t>(std::clamp(x_mm / cell_mm, 0.0, double(along.size())));
  };
  const std::vector<double> middle_along(
      along.begin() + static_cast<std::ptrdiff_t>(column(margin_mm + stroke.size_mm)),
      along.begin() +
          static_cast<std::ptrdiff_t>(column(margin_mm + stroke.length_mm - stroke.size_mm)));
  const double film = median_of(middle_along);
  const SamplingTrace trace =
      sampling_trace(middle_along, cell_mm, stroke.spacing_mm, kTraceSmoothingMm, film);
  f.trace_rms_share = trace.rms_share;
  f.trace_peak = trace.peak;
  f.trace_peak_share = trace.peak_share;
  const double end_mm = margin_mm + stroke.length_mm;
  f.lift_rim_share =
      film > 0.0 ? ridge_prominence(along, column(end_mm - 1.5 * stroke.size_mm),
                                    column(end_mm + stroke.size_mm),
                                    static_cast<std::size_t>(0.5 * stroke.size_mm / cell_mm)) /
                       film
                 : 0.0;
  return f;
}

}  // namespace impasto::bench
