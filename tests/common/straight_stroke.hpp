#pragma once
// One stroke straight along x: pen samples 10 ms apart at x0 + dx·i, i = 0..steps, all at
// one height and pressure, as the render and crack tests paint their ridges.
#include "impasto/paintcore/painting.hpp"

namespace impasto::test {

struct StraightStroke {
  double x0_mm, dx_mm, y_mm;
  int steps;
  float pressure;
  unsigned buttons = paintcore::kPenTip | paintcore::kPenInRange;
};

inline void paint_straight_stroke(paintcore::Painting& painting, const StraightStroke& stroke) {
  painting.begin_stroke();
  for (int i = 0; i <= stroke.steps; ++i) {
    paintcore::PenSample sample;
    sample.time_s = 0.01 * i;
    sample.x_mm = stroke.x0_mm + stroke.dx_mm * i;
    sample.y_mm = stroke.y_mm;
    sample.pressure = stroke.pressure;
    sample.buttons = stroke.buttons;
    painting.stroke_to(sample);
  }
  painting.end_stroke();
}

}  // namespace impasto::test
