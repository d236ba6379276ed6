// Tablet area mapping, pressure curves and the sample queue.
#include <impasto/input/sample_queue.hpp>
#include <impasto/input/tablet_mapping.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>

namespace impasto::input {
namespace {

TEST(AreaMapping, StretchMapsCornersToCorners) {
  const AreaMapping m({0, 0, 200, 100}, {10, 20, 1920, 1080}, false);
  EXPECT_EQ(m.used_tablet_area(), (Rect{0, 0, 200, 100}));
  Point p = m.map(0, 0);
  EXPECT_DOUBLE_EQ(p.x, 10);
  EXPECT_DOUBLE_EQ(p.y, 20);
  p = m.map(200, 100);
  EXPECT_DOUBLE_EQ(p.x, 1930);
  EXPECT_DOUBLE_EQ(p.y, 1100);
  p = m.map(50, 25);
  EXPECT_DOUBLE_EQ(p.x, 10 + 480);
  EXPECT_DOUBLE_EQ(p.y, 20 + 270);
}

TEST(AreaMapping, KeepAspectUsesACentredPartOfTheTablet) {
  // A 200 x 100 mm tablet onto a square: the middle 100 x 100 mm is used.
  const AreaMapping m({0, 0, 200, 100}, {0, 0, 1000, 1000}, true);
  EXPECT_EQ(m.used_tablet_area(), (Rect{50, 0, 100, 100}));
  Point p = m.map(100, 50);
  EXPECT_DOUBLE_EQ(p.x, 500);
  EXPECT_DOUBLE_EQ(p.y, 500);
  // Equal distances on the tablet are equal distances on the target in both axes.
  const Point a = m.map(60, 10);
  const Point b = m.map(70, 20);
  EXPECT_DOUBLE_EQ(b.x - a.x, b.y - a.y);
  // Outside the used area: onto the edge.
  p = m.map(10, 120);
  EXPECT_DOUBLE_EQ(p.x, 0);
  EXPECT_DOUBLE_EQ(p.y, 1000);
}

TEST(AreaMapping, TallTargetCropsHeight) {
  EXPECT_EQ(fit_aspect({0, 0, 100, 100}, {0, 0, 50, 100}), (Rect{25, 0, 50, 100}));
  EXPECT_EQ(fit_aspect({0, 0, 100, 100}, {0, 0, 100, 50}), (Rect{0, 25, 100, 50}));
}

TEST(AreaMapping, MapsSamplesKeepingTheRest) {
  const AreaMapping m({0, 0, 100, 100}, {0, 0, 10, 10}, false);
  paintcore::PenSample s;
  s.x_mm = 50;
  s.y_mm = 20;
  s.pressure = 0.5f;
  s.buttons = paintcore::kPenTip;
  const paintcore::PenSample mapped = m.map(s);
  EXPECT_DOUBLE_EQ(mapped.x_mm, 5);
  EXPECT_DOUBLE_EQ(mapped.y_mm, 2);
  EXPECT_EQ(mapped.pressure, 0.5f);
  EXPECT_EQ(mapped.buttons, paintcore::kPenTip);
}

TEST(AreaMapping, RejectsEmptyOrNonFiniteAreas) {
  EXPECT_THROW(AreaMapping({0, 0, 0, 10}, {0, 0, 1, 1}, false), std::invalid_argument);
  EXPECT_THROW(AreaMapping({0, 0, 1, 1}, {0, 0, NAN, 1}, true), std::invalid_argument);
}

TEST(PressureCurve, GammaIsAPower) {
  const PressureCurve identity;
  const PressureCurve soft = PressureCurve::gamma(2.0);
  for (double p : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    EXPECT_DOUBLE_EQ(identity.apply(p), p);
    EXPECT_DOUBLE_EQ(soft.apply(p), p * p);
  }
  EXPECT_DOUBLE_EQ(soft.apply(-1.0), 0.0);  // clamped into 0..1
  EXPECT_DOUBLE_EQ(soft.apply(2.0), 1.0);
  EXPECT_DOUBLE_EQ(soft.apply(NAN), 0.0);
  EXPECT_THROW(PressureCurve::gamma(0.0), std::invalid_argument);
}

TEST(PressureCurve, BezierWithThirdsIsTheIdentity) {
  const PressureCurve line = PressureCurve::bezier(1.0 / 3, 1.0 / 3, 2.0 / 3, 2.0 / 3);
  for (double p = 0.0; p <= 1.0; p += 0.05) EXPECT_NEAR(line.apply(p), p, 1e-12);
}

TEST(PressureCurve, BezierMatchesItsPolynomial) {
  // With x1 = 1/3, x2 = 2/3 the parameter is the pressure, and
  // y(t) = 3(1-t)^2 t y1 + 3(1-t) t^2 y2 + t^3.
  const double y1 = 0.8, y2 = 0.1;
  const PressureCurve curve = PressureCurve::bezier(1.0 / 3, y1, 2.0 / 3, y2);
  for (double t = 0.0; t <= 1.0; t += 0.1) {
    const double expected = 3 * (1 - t) * (1 - t) * t * y1 + 3 * (1 - t) * t * t * y2 + t * t * t;
    EXPECT_NEAR(curve.apply(t), expected, 1e-12) << t;
  }
  EXPECT_NEAR(curve.apply(0.0), 0.0, 1e-12);
  EXPECT_NEAR(curve.apply(1.0), 1.0, 1e-12);
  EXPECT_THROW(PressureCurve::bezier(1.5, 0, 0, 0), std::invalid_argument);
}

TEST(PressureCurve, BezierIsMonotoneForMonotoneControls) {
  const PressureCurve curve = PressureCurve::bezier(0.9, 0.1, 0.1, 0.9);
  double previous = 0.0;
  for (double p = 0.0; p <= 1.0; p += 0.01) {
    const double y = curve.apply(p);
    EXPECT_GE(y, previous - 1e-12);
    previous = y;
  }
}

TEST(SampleQueue, KeepsOrderAndDropsTheOldestWhenFull) {
  SampleQueue queue(3);
  for (int i = 0; i < 5; ++i) {
    paintcore::PenSample s;
    s.time_s = i;
    queue.push(s);
  }
  EXPECT_EQ(queue.dropped(), 2u);
  const auto samples = queue.drain();
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_EQ(samples[0].time_s, 2.0);
  EXPECT_EQ(samples[2].time_s, 4.0);
  EXPECT_TRUE(queue.drain().empty());
}

TEST(SampleQueue, ManyProducersOneConsumer) {
  SampleQueue queue(100000);
  constexpr int kPerThread = 5000;
  std::vector<std::thread> producers;
  for (int t = 0; t < 4; ++t) {
    producers.emplace_back([&queue, t] {
      for (int i = 0; i < kPerThread; ++i) {
        paintcore::PenSample s;
        s.time_s = t * kPerThread + i;
        queue.push(s);
      }
    });
  }
  std::size_t received = 0;
  std::vector<double> last(4, -1.0);
  bool ordered = true;
  while (received < 4u * kPerThread) {
    for (const auto& s : queue.drain()) {
      const int t = static_cast<int>(s.time_s) / kPerThread;
      ordered = ordered && s.time_s > last[static_cast<std::size_t>(t)];
      last[static_cast<std::size_t>(t)] = s.time_s;
      ++received;
    }
  }
  for (auto& p : producers) p.join();
  EXPECT_TRUE(ordered);  // each producer's samples arrive in its order
  EXPECT_EQ(queue.dropped(), 0u);
}

}  // namespace
}  // namespace impasto::input
