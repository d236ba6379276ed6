// The contact's row kernels: the aligned fast path against the general bilinear one, and the
// film split's bounds.
#include "contact_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace impasto::paintcore {
namespace {

struct TestHead {
  int n = 12;
  std::vector<float> coverage, footprint, paint, coverage_t, footprint_t;
  explicit TestHead(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int padded = n + 2;
    coverage.assign(static_cast<std::size_t>(padded * padded), 0.0f);
    footprint.assign(coverage.size(), 0.0f);
    paint.resize(static_cast<std::size_t>(n * n));
    for (int j = 1; j <= n; ++j)
      for (int i = 1; i <= n; ++i) {
        const auto p = static_cast<std::size_t>(j * padded + i);
        coverage[p] = unit(random) < 0.85f ? unit(random) : 0.0f;
        footprint[p] = 0.3f * unit(random);
      }
    for (float& h : paint) h = unit(random) < 0.2f ? 0.0f : 0.5f * unit(random);
    coverage_t.resize(coverage.size());
    footprint_t.resize(coverage.size());
    for (int j = 0; j < padded; ++j)
      for (int i = 0; i < padded; ++i) {
        coverage_t[static_cast<std::size_t>(i * padded + j)] =
            coverage[static_cast<std::size_t>(j * padded + i)];
        footprint_t[static_cast<std::size_t>(i * padded + j)] =
            footprint[static_cast<std::size_t>(j * padded + i)];
      }
  }
  HeadRow row(float u0, float v0, float step_u, float step_v) const {
    HeadRow h{coverage.data(), footprint.data(), paint.data(), n};
    h.u0 = u0, h.v0 = v0, h.step_u = step_u, h.step_v = step_v, h.tip_mm = 0.1f;
    h.inv_touch_mm = 1.0f / 0.2f;
    h.surface_mm = 0.05f;  // the drag fades in across the footprint's heights
    h.coverage_transposed = coverage_t.data();
    h.footprint_transposed = footprint_t.data();
    return h;
  }
};

struct RowResult {
  std::vector<float> pen, weight, on_brush, touch;
  std::vector<std::int32_t> cell;
  int contacts = 0;
};

template <typename Kernel>
RowResult run(int width, const std::vector<float>& ground, const std::vector<float>& wet,
              Kernel kernel) {
  RowResult r;
  r.pen.resize(static_cast<std::size_t>(width));
  r.weight.resize(r.pen.size());
  r.on_brush.resize(r.pen.size());
  r.touch.resize(r.pen.size());
  r.cell.resize(r.pen.size());
  r.contacts = kernel(width, ground.data(), wet.data(), r.pen.data(), r.cell.data(),
                      r.weight.data(), r.on_brush.data(), r.touch.data());
  return r;
}

// Every canvas row across the head, for a head square to the rows (step along u) and one
// turned a quarter (step along v), splayed so that cells share brush cells.
TEST(ContactRows, AlignedKernelAgreesWithTheBilinearOne) {
  const TestHead head(7);
  const int width = 24;
  std::vector<float> ground(width), wet(width);
  for (int x = 0; x < width; ++x) {
    ground[static_cast<std::size_t>(x)] = 0.05f * static_cast<float>(x % 3);
    wet[static_cast<std::size_t>(x)] = 0.02f * static_cast<float>(x % 5);
  }
  int rows = 0, touching = 0;
  for (const bool along_v : {false, true})
    for (float s = -1.3f; s < 15.0f; s += 0.37f) {
      const float t0 = -2.1f, step = 0.8f;
      const HeadRow h = along_v ? head.row(s, t0, 0.0f, step) : head.row(t0, s, step, 0.0f);
      const RowResult general =
          run(width, ground, wet, [&](int w, auto... a) { return penetrate_row(0, w, h, a...); });
      const RowResult aligned = run(width, ground, wet, [&](int w, auto... a) {
        return penetrate_aligned_row(w, h, along_v, a...);
      });
      ++rows;
      touching += general.contacts;
      ASSERT_EQ(general.contacts, aligned.contacts) << "s " << s << " along_v " << along_v;
      for (int x = 0; x < width; ++x) {
        const auto i = static_cast<std::size_t>(x);
        ASSERT_EQ(general.cell[i], aligned.cell[i]) << "x " << x << " s " << s;
        EXPECT_NEAR(general.pen[i], aligned.pen[i], 1e-6f);
        EXPECT_NEAR(general.weight[i], aligned.weight[i], 1e-5f);
        EXPECT_EQ(general.on_brush[i], aligned.on_brush[i]);
        EXPECT_NEAR(general.touch[i], aligned.touch[i], 1e-5f);
      }
    }
  EXPECT_GT(rows, 80);
  EXPECT_GT(touching, 300);  // the rows really cross the head
}

// A turned head crosses part of each row: the kernel run over head_span only, the rest
// cleared, gives the whole row's result exactly.
TEST(ContactRows, TheHeadsSpanHoldsEveryContact) {
  const TestHead head(11);
  const int width = 40;
  std::vector<float> ground(width, 0.02f), wet(width, 0.05f);
  int rows = 0, partial = 0;
  for (float angle = 0.1f; angle < 6.2f; angle += 0.37f)
    for (float row = -12.0f; row < 30.0f; row += 1.0f) {
      // The row y = row in canvas cells, the head centred at (20, 9), splayed by 1.2.
      const float c = std::cos(angle) / 1.2f, s = std::sin(angle) / 1.2f;
      const float half = 0.5f * static_cast<float>(head.n) + 0.5f;  // padded centre
      const float dx0 = -20.0f, dy = row - 9.0f;
      const HeadRow h = head.row(c * dx0 + s * dy + half, -s * dx0 + c * dy + half, c, -s);
      const RowResult whole =
          run(width, ground, wet, [&](int w, auto... a) { return penetrate_row(0, w, h, a...); });
      int begin, end;
      head_span(width, h, begin, end);
      RowResult part = whole;
      clear_contact(0, width, part.pen.data(), part.cell.data(), part.weight.data(),
                    part.on_brush.data(), part.touch.data());
      part.contacts =
          penetrate_row(begin, end, h, ground.data(), wet.data(), part.pen.data(), part.cell.data(),
                        part.weight.data(), part.on_brush.data(), part.touch.data());
      ++rows;
      partial += (end - begin < width) ? 1 : 0;
      ASSERT_EQ(whole.contacts, part.contacts) << angle << " " << row;
      EXPECT_EQ(whole.cell, part.cell);
      EXPECT_EQ(whole.pen, part.pen);
      EXPECT_EQ(whole.weight, part.weight);
      EXPECT_EQ(whole.touch, part.touch);
    }
  EXPECT_GT(partial, rows / 4);  // the span really cuts rows short
}

// The film split never takes more than deposit_share of what the tips present, nor more than
// the canvas holds, and nothing moves where nothing touches.
TEST(ContactRows, TransferStaysWithinTheFilmSplitsBounds) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const int width = 64;
  std::vector<std::int32_t> cell(width);
  std::vector<float> on_brush(width), cap(width), pen(width), ground(width), wet(width),
      new_wet(width), xfer(width), ratio(width), touch(width);
  for (int x = 0; x < width; ++x) {
    const auto i = static_cast<std::size_t>(x);
    cell[i] = x % 7 == 0 ? -1 : x;
    on_brush[i] = cell[i] < 0 ? 0.0f : 2.0f * unit(random);
    cap[i] = on_brush[i] * unit(random);
    pen[i] = 0.2f * unit(random);
    touch[i] = cell[i] < 0 ? 0.0f : unit(random);
    ground[i] = 0.1f * unit(random);
    wet[i] = x % 5 == 0 ? 0.0f : unit(random);
    new_wet[i] = wet[i];
  }
  const std::vector<float> before = new_wet;
  const FilmSplit split{0.6f, 0.7f, 0.25f, 1.0f, 0.05f};
  transfer_row(width, split, cell.data(), on_brush.data(), cap.data(), touch.data(), pen.data(),
               ground.data(), wet.data(), new_wet.data(), xfer.data(), ratio.data());
  for (int x = 0; x < width; ++x) {
    const auto i = static_cast<std::size_t>(x);
    if (cell[i] < 0) {
      EXPECT_EQ(xfer[i], 0.0f);
      continue;
    }
    const float presented = std::min({on_brush[i], split.tip_film_mm, cap[i]});
    EXPECT_LE(xfer[i], split.deposit_share * presented) << x;
    EXPECT_GE(xfer[i], -(1.0f - split.deposit_share) * before[i] - 1e-6f) << x;
    EXPECT_FLOAT_EQ(new_wet[i], before[i] + xfer[i]);
    EXPECT_TRUE(std::isfinite(ratio[i]));
  }
}

// Contact fades in from its edge: across a row whose paint surface rises through the head's
// underside, how fully the films join (touch) grows with the contact's depth over touch_mm,
// from 0 where the contact begins, with no jump a cell (an all-or-nothing contact left each
// step's edge in the paint: rings in an eased-off dab). The head covers every cell fully, so
// it moves the paint it touches in full (weight; the drag's own fade is the Stepper's).
TEST(ContactRows, TheContactFadesInFromItsEdge) {
  TestHead head(5);
  std::fill(head.footprint.begin(), head.footprint.end(), 0.0f);
  std::fill(head.footprint_t.begin(), head.footprint_t.end(), 0.0f);
  for (int j = 1; j <= head.n; ++j)
    for (int i = 1; i <= head.n; ++i) {
      const auto p = static_cast<std::size_t>(j * (head.n + 2) + i);
      head.coverage[p] = 1.0f;
      head.coverage_t[p] = 1.0f;
    }
  std::fill(head.paint.begin(), head.paint.end(), 0.05f);
  const float touch_mm = 0.2f, rise_per_cell = 0.01f;
  HeadRow h = head.row(1.0f, 6.5f, 0.25f, 0.0f);  // 44 canvas cells cross the head
  h.inv_touch_mm = 1.0f / touch_mm;
  const int width = 44;
  std::vector<float> ground(width, 0.0f), wet(width);
  for (int x = 0; x < width; ++x)  // the surface climbs from 0.2 mm below the tip
    wet[static_cast<std::size_t>(x)] = rise_per_cell * static_cast<float>(x);
  h.tip_mm = 0.2f;
  h.surface_mm = 1.0f;  // the head reaches far below the surface: it drags all it touches
  const RowResult r =
      run(width, ground, wet, [&](int w, auto... a) { return penetrate_row(0, w, h, a...); });
  int first = -1;
  for (int x = 0; x < width; ++x) {
    const auto i = static_cast<std::size_t>(x);
    const float penetration = wet[i] - h.tip_mm;
    const float depth = penetration + 0.05f;  // the paint under the bristles touches first
    if (r.cell[i] < 0) {
      EXPECT_LE(depth, 0.0f) << x;
      EXPECT_EQ(r.touch[i], 0.0f);
      EXPECT_EQ(r.weight[i], 0.0f);
      continue;
    }
    if (first < 0) first = x;
    EXPECT_NEAR(r.touch[i], std::min(depth / touch_mm, 1.0f), 1e-5f) << x;
    EXPECT_EQ(r.weight[i], 1.0f) << x;
    EXPECT_NEAR(r.pen[i], std::max(penetration, 0.0f), 1e-6f) << x;
    if (x > 0) {  // no jump: a cell adds at most its rise
      EXPECT_LE(r.touch[i] - r.touch[i - 1], rise_per_cell / touch_mm + 1e-5f) << x;
    }
  }
  ASSERT_GT(first, 0);
  EXPECT_LT(r.touch[static_cast<std::size_t>(first)], 0.06f);  // begins near 0
  EXPECT_EQ(r.touch[width - 1], 1.0f);                         // and joins fully inside

  // The drag fades in as the underside comes down to the surface around the brush's centre,
  // whatever each cell's own paint: half the fade's depth above it, half the drag.
  h.surface_mm = h.tip_mm - 0.5f * touch_mm;
  const RowResult half =
      run(width, ground, wet, [&](int w, auto... a) { return penetrate_row(0, w, h, a...); });
  for (int x = first; x < width; ++x)
    EXPECT_FLOAT_EQ(half.weight[static_cast<std::size_t>(x)], 0.5f) << x;

  // Where the films do not join, the split moves nothing; half joined, half as far.
  std::vector<std::int32_t> cell(3, 0);
  std::vector<float> on_brush(3, 0.5f), touch{0.0f, 0.5f, 1.0f}, pen(3, 0.1f), flat(3, 0.0f),
      film(3, 0.2f), new_wet = film, xfer(3), ratio(3);
  const FilmSplit split{2.5f, 0.5f, 0.25f, 0.0f, 0.0f};
  transfer_row(3, split, cell.data(), on_brush.data(), on_brush.data(), touch.data(), pen.data(),
               flat.data(), film.data(), new_wet.data(), xfer.data(), ratio.data());
  EXPECT_EQ(xfer[0], 0.0f);
  EXPECT_NE(xfer[2], 0.0f);
  EXPECT_NEAR(xfer[1], 0.5f * xfer[2], 1e-6f);
}

}  // namespace
}  // namespace impasto::paintcore
