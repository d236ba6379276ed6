#pragma once
// What one standard stroke leaves, for each head and paint body: the figures of
// `impasto bench marks` (docs/marks.md). The stroke: a head of `size_mm` loaded with
// 200 mm^3 x (size / 8 mm)^2 of paint (a brush holds paint by its width, whatever its
// footprint), drawn 50 mm along +x at pressure 0.7 in one second, sampled every 0.1 mm, on
// a flat canvas.
#include <string>

#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore {

struct MarkFigures {
  std::string head;
  PaintBody body = kDefaultPaintBody;
  double size_mm = 0;
  double load_mm3 = 0;
  double deposited_share = 0;  // canvas volume / load
  PaintThickness thickness;
  double edge_ridge_mm = 0;       // edge crest above the middle third's median, across
  double furrow_period_mm = 0;    // dominant period of the thickness across the stroke
  double bristle_spacing_mm = 0;  // the head's spacing, splayed at the stroke's pressure
  double middle_mm = 0;           // median thickness of the middle third across the stroke
  double furrow_rms_mm = 0;       // furrows' depth (RMS) at the splayed bristle spacing
  double width_mm = 0;            // painted width across the stroke's middle
  double seconds_per_step = 0;    // wall time of the stroke / simulation steps
  std::uint64_t steps = 0;
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
  SimulationParams params;
};

// The dominant period (mm) of the paint's thickness across a stroke drawn along x, from a
// discrete Fourier transform of its profile averaged over canvas columns [x0, x1), over the
// middle three fifths of the painted band (the edge ridges left out); 0 where none is painted.
double furrow_period_mm(const Canvas& canvas, int x0, int x1);

// The furrows' depth (RMS, mm) of the same profile and band: the profile less its running
// mean over one `period_mm` (the bristles' spacing), which removes the mark's broad shape.
double furrow_rms_mm(const Canvas& canvas, int x0, int x1, double period_mm);

// Paints the standard stroke with head `head` (from the brushes folder) and `body`.
MarkFigures measure_mark(const std::string& head, PaintBody body, const MarkStroke& stroke = {});

}  // namespace impasto::paintcore
