// Paint is conserved: canvas + brush = loaded - wiped, over whole sessions, for any pose;
// and results are deterministic, for any number of threads.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::expect_conserved;
using test::flat_spec;
using test::relative_error;
using test::round_brush;

// A session of strokes in many directions, with tilt and twist, reloads and wipes.
void paint_session(Painting& p) {
  SimulationParams params;
  p.set_params(params);
  p.set_brush(round_brush(1.5, 0.3));
  const char* colours[] = {"red", "blue", "white"};
  for (int k = 0; k < 9; ++k) {
    if (k % 3 == 0) p.load_brush({{colours[k % 3], 1.0}, {colours[(k + 1) % 3], 0.5}}, 4.0);
    if (k == 4) p.wipe_brush();
    if (k == 5) p.set_brush(BrushSettings{"filbert", 1.5, 0.7});
    const double a = 0.7 * k;
    p.begin_stroke();
    for (int i = 0; i <= 24; ++i) {
      const double t = i / 24.0;
      PenSample s =
          test::pen(6.0 + 4.0 * std::cos(a) * (t - 0.5) + 0.5 * std::sin(9 * t),
                    6.0 + 4.0 * std::sin(a) * (t - 0.5), static_cast<float>(0.3 + 0.7 * t),
                    static_cast<float>(25.0 * std::sin(a)), static_cast<float>(20.0 * t),
                    static_cast<float>(37.0 * k + 90.0 * t));
      p.stroke_to(s);
    }
    p.end_stroke();
  }
}

TEST(Conservation, SingleStrokeIsConservedPerStep) {
  Painting p(flat_spec(64, 64));
  p.set_brush(round_brush());
  p.load_brush({{"a", 1.0}, {"b", 2.0}}, 3.0);
  p.begin_stroke();
  for (int i = 0; i < 30; ++i) {
    p.stroke_to(test::pen(1.0 + 0.15 * i, 3.0 + 0.05 * i, 0.9f, 10.0f, -30.0f, 12.0f * i));
    expect_conserved(p);
  }
  p.end_stroke();
}

TEST(Conservation, LongSessionWithLoadsAndWipes) {
  Painting p(CanvasSpec{128, 128, 254.0, 3});  // on a woven canvas
  paint_session(p);
  EXPECT_GT(p.steps(), 500u);
  EXPECT_GT(p.wiped_totals().volume, 0.0);
  expect_conserved(p);
  p.dry(0.5);
  expect_conserved(p);
}

TEST(Conservation, RotatedAndTiltedFlatBrush) {
  Painting p(flat_spec(64, 64));
  SimulationParams params;
  p.set_params(params);
  p.set_brush(BrushSettings{"flat", 3.0, 0.2});
  p.load_brush({{"ochre", 1.0}}, 10.0);
  test::stroke_line(p, 1.0, 1.0, 5.5, 5.0, 1.0f, 15, 40.0f, -35.0f, 63.0f);
  EXPECT_GT(p.canvas_totals().volume, 0.0);
  expect_conserved(p, 1e-6);
}

TEST(Determinism, SameInputSameHash) {
  Painting a(CanvasSpec{128, 128, 254.0, 3}, 2);
  Painting b(CanvasSpec{128, 128, 254.0, 3}, 2);
  paint_session(a);
  paint_session(b);
  EXPECT_EQ(a.state_hash(), b.state_hash());
}

TEST(Determinism, OneAndTwoThreadsAgreeBitForBit) {
  // A big brush, so that the rows really are split among threads.
  const auto run = [](int threads) {
    Painting p(CanvasSpec{160, 160, 254.0, 9}, threads);
    p.set_brush(round_brush(7.0, 0.2));
    p.load_brush({{"a", 1.0}, {"b", 1.0}}, 100.0);
    test::stroke_line(p, 4.0, 4.0, 10.0, 9.0, 0.9f, 10, 20.0f, 0.0f, 30.0f);
    test::stroke_line(p, 10.0, 4.0, 4.0, 9.0, 0.7f, 10);
    return p.state_hash();
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(Determinism, HashSeesEveryChange) {
  Painting p(flat_spec(64, 64));
  const std::uint64_t empty = p.state_hash();
  p.set_brush(round_brush());
  const std::uint64_t with_brush = p.state_hash();
  EXPECT_NE(empty, with_brush);
  p.load_brush({{"a", 1.0}}, 1.0);
  EXPECT_NE(p.state_hash(), with_brush);
}

}  // namespace
}  // namespace impasto::paintcore
