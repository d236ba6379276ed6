#pragma once
// What one standard stroke leaves, for each head and paint body: the figures of
// `impasto bench marks` (docs/marks.md). The stroke: a head of `size_mm` loaded with
// 200 mm^3 x (size / 8 mm)^2 of paint (a brush holds paint by its width, whatever its
// footprint), drawn 50 mm along +x at pressure 0.7 in one second, sampled every 0.1 mm, on
// a flat canvas.
#include <string>

#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::bench {

struct MarkFigures {
  std::string head;
  paintcore::PaintBody body = paintcore::kDefaultPaintBody;
  double size_mm = 0;
  double dpi = 0;
  double spacing_mm = 0;  // between pen samples
  double load_mm3 = 0;
  double deposited_share = 0;  // canvas volume / load
  paintcore::PaintThickness thickness;
  double edge_ridge_mm = 0;       // edge crest above the middle third's median, across
  double furrow_period_mm = 0;    // dominant period of the thickness across the stroke
  double bristle_spacing_mm = 0;  // the head's spacing, splayed at the stroke's pressure
  double middle_mm = 0;           // median thickness of the middle third across the stroke
  double furrow_rms_mm = 0;       // furrows' depth (RMS) at the splayed bristle spacing
  double width_mm = 0;            // painted width across the stroke's middle
  double seconds_per_step = 0;    // wall time of the stroke / simulation steps
  std::uint64_t steps = 0;
  // The pen's sampling left in the paint (the profile along the stroke's middle, less its
  // running mean over 3 mm: what varies faster than the hand does).
  double trace_rms_share = 0;   // its RMS over the middle third's median thickness
  double trace_peak = 0;        // its power at the event frequency over the neighbours' median
  double trace_peak_share = 0;  // that component's amplitude over the film
  // Where the brush lifts: the most prominent ridge crossing the stroke in its last 1.5 head
  // widths (or beyond it), over the middle third's median thickness.
  double lift_rim_share = 0;
};

struct MarkStroke {
  double dpi = 254.0;
  double size_mm = 8.0;
  double length_mm = 50.0;
  double seconds = 1.0;
  double spacing_mm = 0.1;
  float pressure = 0.7f;
  double load_mm3_at_8mm = 200.0;  // the load of an 8 mm head, scaled by the size squared
  int threads = 0;
  paintcore::SimulationParams params;
};

// The dominant period (mm) of the paint's thickness across a stroke drawn along x, from a
// discrete Fourier transform of its profile averaged over canvas columns [x0, x1), over the
// middle three fifths of the painted band (the edge ridges left out); 0 where none is painted.
double furrow_period_mm(const paintcore::Canvas& canvas, int x0, int x1);

// The furrows' depth (RMS, mm) of the same profile and band: the profile less its running
// mean over one `period_mm` (the bristles' spacing), which removes the mark's broad shape.
double furrow_rms_mm(const paintcore::Canvas& canvas, int x0, int x1, double period_mm);

// The trace of a sampling period on a profile along a stroke (mm, one value a cell): the
// profile less its running mean over `smooth_mm`, its RMS over `film_mm`, and its power at
// `period_mm` (the strongest of the bins nearest to it) over the median power of the bins
// from half to twice that frequency, the peak's own bins left out, or over the power of a
// ripple of 0.05 % of the film where that is more (a smooth stroke has next to no texture of
// its own to stand against). A period shorter than three cells cannot be resolved: its peak
// is 0.
struct SamplingTrace {
  double rms_share = 0;
  double peak = 0;        // see sampling_trace
  double peak_share = 0;  // the amplitude at `period_mm` over the film
};
SamplingTrace sampling_trace(const std::vector<double>& along, double cell_mm, double period_mm,
                             double smooth_mm, double film_mm);

// The most prominent ridge of `along` within [begin, end): each value's height above the
// higher of the lowest values within `reach` cells on either side (a crest standing over a
// plateau on one side and the bare canvas on the other counts from the plateau).
double ridge_prominence(const std::vector<double>& along, std::size_t begin, std::size_t end,
                        std::size_t reach);

// Paints the standard stroke with head `head` (from the brushes folder) and `body`.
MarkFigures measure_mark(const std::string& head, paintcore::PaintBody body,
                         const MarkStroke& stroke = {});

}  // namespace impasto::bench
