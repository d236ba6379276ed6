#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "impasto/paintcore/advection.hpp"

namespace impasto::paintcore {
namespace {

// A padded 1-row window of `width` cells (see advection.hpp for the layout).
struct Row {
  int width;
  std::vector<float> vx, vy, q, out;
  explicit Row(int w)
      : width(w), vx(pad(), 0.0f), vy(pad(), 0.0f), q(pad(), 0.0f), out(pad(), 0.0f) {}
  std::size_t pad() const { return static_cast<std::size_t>(width + 2) * 3; }
  std::size_t at(int x) const { return static_cast<std::size_t>(width + 2 + x + 1); }
  double total(const std::vector<float>& v) const {
    return std::accumulate(v.begin(), v.end(), 0.0);
  }
};

TEST(Advection, BlockTranslatesOneCellAtFullSpeed) {
  Row r(10);
  for (int x = 2; x <= 4; ++x) r.q[r.at(x)] = 1.0f;
  for (int x = 0; x < 9; ++x) r.vx[r.at(x)] = 1.0f;
  Advection a;
  a.prepare(10, 1, r.vx.data(), r.vy.data(), r.q.data(), 0.0f);
  a.apply(r.q.data(), r.out.data());
  for (int x = 0; x < 10; ++x) EXPECT_FLOAT_EQ(r.out[r.at(x)], (x >= 3 && x <= 5) ? 1.0f : 0.0f);
}

TEST(Advection, HalfCellStepSplitsTheEdgesAndConserves) {
  Row r(10);
  for (int x = 2; x <= 4; ++x) r.q[r.at(x)] = 1.0f;
  for (int x = 0; x < 9; ++x) r.vx[r.at(x)] = 0.5f;
  Advection a;
  a.prepare(10, 1, r.vx.data(), r.vy.data(), r.q.data(), 0.0f);
  a.apply(r.q.data(), r.out.data());
  const float expected[10] = {0, 0, 0.5f, 1, 1, 0.5f, 0, 0, 0, 0};
  for (int x = 0; x < 10; ++x) EXPECT_FLOAT_EQ(r.out[r.at(x)], expected[x]) << x;
  EXPECT_DOUBLE_EQ(r.total(r.out), 3.0);
}

TEST(Advection, NegativeVelocityMovesWest) {
  Row r(6);
  r.q[r.at(3)] = 2.0f;
  r.vx[r.at(3)] = -0.25f;
  Advection a;
  a.prepare(6, 1, r.vx.data(), r.vy.data(), r.q.data(), 0.0f);
  a.apply(r.q.data(), r.out.data());
  EXPECT_FLOAT_EQ(r.out[r.at(2)], 0.5f);
  EXPECT_FLOAT_EQ(r.out[r.at(3)], 1.5f);
  EXPECT_FLOAT_EQ(r.out[r.at(4)], 0.0f);
}

TEST(Advection, MinimumFilmStaysBehind) {
  Row r(10);
  for (int x = 2; x <= 4; ++x) r.q[r.at(x)] = 1.0f;
  for (int x = 0; x < 9; ++x) r.vx[r.at(x)] = 1.0f;
  Advection a;
  a.prepare(10, 1, r.vx.data(), r.vy.data(), r.q.data(), 0.2f);
  a.apply(r.q.data(), r.out.data());
  // Each full cell may give only 0.8: 0.2 stays, 0.8 arrives next door.
  const float expected[10] = {0, 0, 0.2f, 1, 1, 0.8f, 0, 0, 0, 0};
  for (int x = 0; x < 10; ++x) EXPECT_NEAR(r.out[r.at(x)], expected[x], 1e-6) << x;
  EXPECT_NEAR(r.total(r.out), 3.0, 1e-6);
  // A cell already thinner than the film gives nothing.
  Row thin(4);
  thin.q[thin.at(1)] = 0.1f;
  thin.vx[thin.at(1)] = 1.0f;
  a.prepare(4, 1, thin.vx.data(), thin.vy.data(), thin.q.data(), 0.2f);
  a.apply(thin.q.data(), thin.out.data());
  EXPECT_FLOAT_EQ(thin.out[thin.at(1)], 0.1f);
}

TEST(Advection, DiagonalStepSplitsIntoFourOverlaps) {
  const int w = 3, h = 3, s = w + 2;
  std::vector<float> vx(25, 0.0f), vy(25, 0.0f), q(25, 0.0f), out(25, 0.0f);
  const auto at = [s](int x, int y) { return static_cast<std::size_t>((y + 1) * s + x + 1); };
  q[at(1, 1)] = 1.0f;
  vx[at(1, 1)] = 0.5f;
  vy[at(1, 1)] = -0.5f;  // towards the row above
  Advection a;
  a.prepare(w, h, vx.data(), vy.data(), q.data(), 0.0f);
  a.apply(q.data(), out.data());
  EXPECT_FLOAT_EQ(out[at(1, 1)], 0.25f);
  EXPECT_FLOAT_EQ(out[at(2, 1)], 0.25f);
  EXPECT_FLOAT_EQ(out[at(1, 0)], 0.25f);
  EXPECT_FLOAT_EQ(out[at(2, 0)], 0.25f);
  EXPECT_FLOAT_EQ(out[at(0, 2)], 0.0f);
}

TEST(Advection, PigmentsMoveWithTheVolume) {
  Row r(8);
  std::vector<float> pigment(r.pad(), 0.0f), pigment_out(r.pad(), 0.0f);
  r.q[r.at(3)] = 1.0f;
  pigment[r.at(3)] = 0.3f;  // concentration 0.3
  r.q[r.at(4)] = 0.5f;
  pigment[r.at(4)] = 0.05f;  // concentration 0.1
  r.vx[r.at(3)] = 0.4f;
  Advection a;
  a.prepare(8, 1, r.vx.data(), r.vy.data(), r.q.data(), 0.0f);
  const float* from[2] = {r.q.data(), pigment.data()};
  float* to[2] = {r.out.data(), pigment_out.data()};
  a.apply(from, to, 2);
  // Cell 4 received 0.4 of paint at concentration 0.3: volume-weighted mixing.
  EXPECT_FLOAT_EQ(r.out[r.at(4)], 0.9f);
  EXPECT_FLOAT_EQ(pigment_out[r.at(4)], 0.05f + 0.12f);
  EXPECT_FLOAT_EQ(pigment_out[r.at(3)] / r.out[r.at(3)], 0.3f);
}

}  // namespace
}  // namespace impasto::paintcore
