// Thick paint buries the canvas weave; thin paint lets it read through. The weave is the
// canvas's own (canvas_weave_height_mm, through Canvas::base_height_mm); its share in the
// painted surface is measured two ways: the surface's projection on the weave, and the
// amplitude at the weave's thread pitch along the stroke against the bare weave's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/paintcore/weave.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

constexpr double kDpi = 254.0;  // 0.1 mm cells: the thread pitch is 6 cells

struct Stroke {
  double size_mm = 3.0, length_mm = 12.0;
  double load_mm3 = 20.0;
  float pressure = 0.7f;
  double x0_mm() const { return 1.5 * size_mm; }
  double y_mm() const { return 1.25 * size_mm; }
};

struct WeaveShare {
  double projection = 0;  // least-squares coefficient of the surface on the weave: 1 bare
  double amplitude = 0;   // |surface| / |weave| at the thread pitch along x, rows' mean
  double paint_mm = 0;    // the paint's mean thickness there
};

// Over the middle of the stroke: the central third of its length, the central third of its
// width (the stroke runs along x).
WeaveShare weave_share(const Painting& p, const Stroke& stroke) {
  const Canvas& c = p.canvas();
  const double cell = c.cell_mm();
  const int pitch = static_cast<int>(std::lround(kWeaveThreadPitchMm / cell));
  const int x0 = static_cast<int>((stroke.x0_mm() + stroke.length_mm / 3.0) / cell);
  const int n = pitch * static_cast<int>(stroke.length_mm / 3.0 / cell / pitch);
  const int y0 = static_cast<int>((stroke.y_mm() - stroke.size_mm / 6.0) / cell);
  const int y1 = static_cast<int>((stroke.y_mm() + stroke.size_mm / 6.0) / cell);
  double sg = 0, gg = 0, surface_amp = 0, weave_amp = 0, paint = 0;
  for (int y = y0; y < y1; ++y) {
    std::vector<double> s(static_cast<std::size_t>(n)), g(s.size());
    for (int i = 0; i < n; ++i) {
      const int x = x0 + i;
      g[static_cast<std::size_t>(i)] = c.base_height_mm(x, y);
      const double on_top = static_cast<double>(c.dry_height_mm(x, y)) + c.wet_volume_mm(x, y);
      s[static_cast<std::size_t>(i)] = g[static_cast<std::size_t>(i)] + on_top;
      paint += on_top;
    }
    // Each row less its straight line (the stroke thins as the brush runs dry).
    for (std::vector<double>* v : {&s, &g}) {
      double mean = 0, slope = 0, xx = 0;
      for (int i = 0; i < n; ++i) mean += (*v)[static_cast<std::size_t>(i)] / n;
      for (int i = 0; i < n; ++i) {
        const double t = i - 0.5 * (n - 1);
        slope += t * ((*v)[static_cast<std::size_t>(i)] - mean);
        xx += t * t;
      }
      for (int i = 0; i < n; ++i)
        (*v)[static_cast<std::size_t>(i)] -= mean + slope / xx * (i - 0.5 * (n - 1));
    }
    std::complex<double> fs, fg;
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      sg += s[k] * g[k];
      gg += g[k] * g[k];
      const std::complex<double> phase = std::polar(1.0, -2.0 * std::numbers::pi * i / pitch);
      fs += s[k] * phase;
      fg += g[k] * phase;
    }
    surface_amp += std::abs(fs);
    weave_amp += std::abs(fg);
  }
  return {sg / gg, surface_amp / weave_amp, paint / (static_cast<double>(n) * (y1 - y0))};
}

// The stroke along +x on a woven canvas (seed 1), a pen sample every 0.1 mm over a second.
WeaveShare paint_on_weave(const Stroke& stroke) {
  const double cell = 25.4 / kDpi;
  Painting p(
      CanvasSpec{static_cast<int>(std::lround((stroke.length_mm + 3.0 * stroke.size_mm) / cell)),
                 static_cast<int>(std::lround(2.5 * stroke.size_mm / cell)), kDpi, 1});
  p.set_brush(test::round_brush(stroke.size_mm));
  p.load_brush({{"white", 1.0}}, stroke.load_mm3);  // heavy body
  const auto samples = std::lround(stroke.length_mm / 0.1);
  p.begin_stroke();
  for (long i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(samples);
    PenSample s = test::pen(stroke.x0_mm() + stroke.length_mm * t, stroke.y_mm(), stroke.pressure);
    s.time_s = t;
    p.stroke_to(s);
  }
  p.end_stroke();
  return weave_share(p, stroke);
}

// A 5 mm round well loaded with heavy paint, and nearly dry, dragged lightly.
constexpr Stroke kThick{5.0, 20.0, 55.0, 0.7f}, kDryBrush{5.0, 20.0, 0.8, 0.3f};

TEST(WeaveBurial, BareCanvasIsAllWeave) {
  Stroke bare_canvas;
  bare_canvas.load_mm3 = 0.0;
  const WeaveShare bare = paint_on_weave(bare_canvas);
  EXPECT_NEAR(bare.projection, 1.0, 1e-9);
  EXPECT_NEAR(bare.amplitude, 1.0, 1e-9);
}

TEST(WeaveBurial, ThickPaintBuriesTheWeave) {
  // Heavy paint well thicker than the weave is deep (0.05 mm): its top follows the brush.
  const WeaveShare thick = paint_on_weave(kThick);
  EXPECT_GT(thick.paint_mm, 4.0 * kWeaveAmplitudeMm);
  EXPECT_LT(std::abs(thick.projection), 0.15) << "paint " << thick.paint_mm << " mm";
  EXPECT_LT(thick.amplitude, 0.25) << "paint " << thick.paint_mm << " mm";
}

TEST(WeaveBurial, DryBrushKeepsTheWeave) {
  // A nearly dry brush dragged lightly leaves a film thinner than the weave: a stain that
  // the weave reads through.
  const WeaveShare thin = paint_on_weave(kDryBrush);
  EXPECT_GT(thin.paint_mm, 0.002);
  EXPECT_LT(thin.paint_mm, 0.5 * kWeaveAmplitudeMm);
  EXPECT_GT(thin.projection, 0.5) << "paint " << thin.paint_mm << " mm";
  EXPECT_GT(thin.amplitude, 0.5) << "paint " << thin.paint_mm << " mm";
}

}  // namespace
}  // namespace impasto::paintcore
