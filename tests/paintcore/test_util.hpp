#pragma once
// Helpers shared by the paintcore tests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "impasto/paintcore/painting.hpp"

namespace impasto::paintcore::test {

// A flat canvas (weave seed 0) of 0.1 mm cells unless told otherwise.
inline CanvasSpec flat_spec(int width = 128, int height = 128, double dpi = 254.0) {
  return CanvasSpec{width, height, dpi, 0};
}

inline BrushSettings round_brush(double size_mm = 2.0, double stiffness = 0.5) {
  BrushSettings s;
  s.head = "round";
  s.size_mm = size_mm;
  s.stiffness = stiffness;
  return s;
}

inline PenSample pen(double x_mm, double y_mm, float pressure, float tilt_x = 0.0f,
                     float tilt_y = 0.0f, float rotation = 0.0f) {
  PenSample s;
  s.x_mm = x_mm;
  s.y_mm = y_mm;
  s.pressure = pressure;
  s.tilt_x_deg = tilt_x;
  s.tilt_y_deg = tilt_y;
  s.rotation_deg = rotation;
  s.buttons = kPenTip;
  return s;
}

// One stroke of `samples` evenly spaced pen samples from (x0, y0) to (x1, y1), in mm.
inline void stroke_line(Painting& p, double x0, double y0, double x1, double y1, float pressure,
                        int samples = 20, float tilt_x = 0, float tilt_y = 0, float rotation = 0) {
  p.begin_stroke();
  for (int i = 0; i < samples; ++i) {
    const double t = samples > 1 ? static_cast<double>(i) / (samples - 1) : 0.0;
    p.stroke_to(pen(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, pressure, tilt_x, tilt_y, rotation));
  }
  p.end_stroke();
}

// Two crossing strokes on a `width_cells` x 70 canvas (0.1 mm cells, weave 3), from the top
// corners 1 mm in down to y = 6 mm: red, then `dried` (0..1) of it dried, then blue. Wet and
// dry paint of two pigments, for the tests that resample a painting.
inline Painting crossed_strokes(int width_cells, double dried) {
  const double right_mm = width_cells / 10.0 - 1.0;
  Painting p(CanvasSpec{width_cells, 70, 254.0, 3}, 1);
  p.set_brush(round_brush(3.0));
  p.load_brush({{"red", 1.0}}, 30.0);
  stroke_line(p, 1.0, 1.0, right_mm, 6.0, 0.8f);
  p.dry(dried);
  p.load_brush({{"blue", 1.0}}, 30.0);
  stroke_line(p, right_mm, 1.0, 1.0, 6.0, 0.9f);
  return p;
}

// Paint that should exist: loaded - wiped; and what does: canvas + brush.
inline PaintTotals expected_totals(const Painting& p) {
  PaintTotals t = p.loaded_totals();
  const PaintTotals w = p.wiped_totals();
  t.volume -= w.volume;
  for (std::size_t s = 0; s < t.pigment.size(); ++s) t.pigment[s] -= w.pigment[s];
  return t;
}

inline PaintTotals present_totals(const Painting& p) {
  PaintTotals t = p.canvas_totals();
  const PaintTotals b = p.brush_totals();
  t.volume += b.volume;
  for (std::size_t s = 0; s < t.pigment.size(); ++s) t.pigment[s] += b.pigment[s];
  return t;
}

inline double relative_error(double actual, double expected) {
  return std::abs(actual - expected) / std::max(std::abs(expected), 1e-300);
}

// Paint is conserved: present = expected, in volume and in every pigment, within `tolerance`
// (relative), and no value is NaN or infinite.
inline void expect_conserved(const Painting& p, double tolerance = 1e-5) {
  const PaintTotals expected = expected_totals(p);
  const PaintTotals present = present_totals(p);
  EXPECT_LT(relative_error(present.volume, expected.volume), tolerance)
      << present.volume << " vs " << expected.volume;
  for (std::size_t s = 0; s < expected.pigment.size(); ++s)
    EXPECT_LT(relative_error(present.pigment[s], expected.pigment[s]), tolerance) << "slot " << s;
  EXPECT_EQ(p.nonfinite_count(), 0u);
}

}  // namespace impasto::paintcore::test
