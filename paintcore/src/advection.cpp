#include "impasto/paintcore/advection.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "parallel_rows.hpp"
#include "simd_clones.hpp"

namespace impasto::paintcore {

namespace {

// What leaves a cell moving by (ax, ay) = |v| holding `volume`: the share of its column the
// translation moves off the cell (the overlap areas, Fig. 4 in 2D), and the scale that keeps
// at least the minimum film behind (adhesion). Branch-free (callers' loops vectorise).
struct Leaving {
  float share;  // of the column, before scaling
  float scale;  // 0..1
};
inline Leaving leaving(float ax, float ay, float volume, float min_film_mm) {
  const float share = ax + ay - ax * ay;
  const float amount = volume * share;
  const float room = volume - min_film_mm;
  const bool moves = amount > 0.0f;
  const float ratio = room / (moves ? amount : 1.0f);  // never divides by zero
  return {share, moves ? std::min(std::max(ratio, 0.0f), 1.0f) : 0.0f};
}

// The shares one row of cells sends. Branch-free so that it vectorises.
IMPASTO_SIMD_CLONES void prepare_row(int width, const float* __restrict vx,
                                     const float* __restrict vy, const float* __restrict volume,
                                     float min_film_mm, float* __restrict stay,
                                     float* __restrict east, float* __restrict west,
                                     float* __restrict south, float* __restrict north,
                                     float* __restrict south_east, float* __restrict south_west,
                                     float* __restrict north_east, float* __restrict north_west) {
  for (int x = 0; x < width; ++x) {
    const float ax = std::abs(vx[x]);
    const float ay = std::abs(vy[x]);
    const auto [leaving_share, scale] = leaving(ax, ay, volume[x], min_film_mm);
    const float px = std::max(vx[x], 0.0f) * scale;
    const float mx = std::max(-vx[x], 0.0f) * scale;
    const float py = std::max(vy[x], 0.0f);
    const float my = std::max(-vy[x], 0.0f);
    stay[x] = 1.0f - scale * leaving_share;
    east[x] = px * (1.0f - ay);
    west[x] = mx * (1.0f - ay);
    south[x] = scale * py * (1.0f - ax);
    north[x] = scale * my * (1.0f - ax);
    south_east[x] = px * py;
    south_west[x] = mx * py;
    north_east[x] = px * my;
    north_west[x] = mx * my;
  }
}

// The shares of a row whose velocities all point into one quadrant: across x (toward
// sign_x), across y and diagonally; the same expressions as prepare_row's.
IMPASTO_SIMD_CLONES void prepare_quadrant_row(int width, const float* __restrict vx,
                                              const float* __restrict vy,
                                              const float* __restrict volume, float min_film_mm,
                                              float* __restrict stay, float* __restrict across_x,
                                              float* __restrict across_y,
                                              float* __restrict diagonal) {
  for (int x = 0; x < width; ++x) {
    const float ax = std::abs(vx[x]);
    const float ay = std::abs(vy[x]);
    const auto [leaving_share, scale] = leaving(ax, ay, volume[x], min_film_mm);
    const float px = ax * scale;
    stay[x] = 1.0f - scale * leaving_share;
    across_x[x] = px * (1.0f - ay);
    across_y[x] = scale * ay * (1.0f - ax);
    diagonal[x] = px * ay;
  }
}

// One row of the gather for a quadrant: what stays, then what the neighbours behind the
// motion send (in prepare_row's order of terms, less those that are 0).
IMPASTO_SIMD_CLONES void gather_quadrant_row(int width, std::ptrdiff_t from_x,
                                             std::ptrdiff_t from_y, const float* __restrict c,
                                             float* __restrict o, const float* __restrict stay,
                                             const float* __restrict across_x,
                                             const float* __restrict across_y,
                                             const float* __restrict diagonal) {
  for (int x = 0; x < width; ++x) {
    float sum = stay[x] * c[x];
    sum += across_x[x + from_x] * c[x + from_x];
    sum += across_y[x + from_y] * c[x + from_y];
    sum += diagonal[x + from_x + from_y] * c[x + from_x + from_y];
    o[x] = sum;
  }
}

// One row of the gather: each cell sums the shares its neighbours send it, in a fixed order
// of terms, so that the sum is the same on any thread.
IMPASTO_SIMD_CLONES void gather_row(int width, std::ptrdiff_t s, const float* __restrict c,
                                    float* __restrict o, const float* __restrict from_self,
                                    const float* __restrict from_w, const float* __restrict from_e,
                                    const float* __restrict from_n, const float* __restrict from_s,
                                    const float* __restrict from_nw,
                                    const float* __restrict from_ne,
                                    const float* __restrict from_sw,
                                    const float* __restrict from_se) {
  for (int x = 0; x < width; ++x) {
    float sum = from_self[x] * c[x];
    sum += from_w[x] * c[x - 1];
    sum += from_e[x] * c[x + 1];
    sum += from_n[x] * c[x - s];
    sum += from_s[x] * c[x + s];
    sum += from_nw[x] * c[x - s - 1];
    sum += from_ne[x] * c[x - s + 1];
    sum += from_sw[x] * c[x + s - 1];
    sum += from_se[x] * c[x + s + 1];
    o[x] = sum;
  }
}

}  // namespace

void Advection::resize(int width, int height) {
  width_ = width;
  height_ = height;
  const std::size_t n = padded_size();
  const int stride = width + 2;
  // Every real cell is written by prepare_rows; only the border needs clearing.
  for (auto* grid :
       {&stay_, &east_, &west_, &south_, &north_, &south_east_, &south_west_, &north_east_,
        &north_west_, &next_stay_, &next_across_x_, &next_across_y_, &next_diagonal_}) {
    if (grid->size() < n) grid->resize(n);
    float* g = grid->data();
    std::fill(g, g + stride, 0.0f);
    std::fill(g + static_cast<std::ptrdiff_t>(height + 1) * stride,
              g + static_cast<std::ptrdiff_t>(height + 2) * stride, 0.0f);
    for (int y = 1; y <= height; ++y) {
      g[static_cast<std::ptrdiff_t>(y) * stride] = 0.0f;
      g[static_cast<std::ptrdiff_t>(y) * stride + width + 1] = 0.0f;
    }
  }
}

void Advection::prepare_rows(int y0, int y1, const float* vx, const float* vy, const float* volume,
                             float min_film_mm) {
  quadrant_x_ = quadrant_y_ = 0;
  const int stride = width_ + 2;
  for (int y = y0; y < y1; ++y) {
    const std::size_t i = static_cast<std::size_t>(y + 1) * stride + 1;
    prepare_row(width_, vx + i, vy + i, volume + i, min_film_mm, stay_.data() + i, east_.data() + i,
                west_.data() + i, south_.data() + i, north_.data() + i, south_east_.data() + i,
                south_west_.data() + i, north_east_.data() + i, north_west_.data() + i);
  }
}

void Advection::prepare_quadrant_rows(int y0, int y1, const float* vx, const float* vy,
                                      const float* volume, float min_film_mm) {
  const int stride = width_ + 2;
  for (int y = y0; y < y1; ++y) {
    const std::size_t i = static_cast<std::size_t>(y + 1) * stride + 1;
    prepare_quadrant_row(width_, vx + i, vy + i, volume + i, min_film_mm, next_stay_.data() + i,
                         next_across_x_.data() + i, next_across_y_.data() + i,
                         next_diagonal_.data() + i);
  }
}

void Advection::prepare_quadrant_spans(int y0, int y1, const float* vx, const float* vy,
                                       const float* volume, float min_film_mm, const int* x0,
                                       const int* x1) {
  const int stride = width_ + 2;
  for (int y = y0; y < y1; ++y) {
    if (x1[y] <= x0[y]) continue;
    const std::size_t i = static_cast<std::size_t>(y + 1) * stride + 1 + x0[y];
    prepare_quadrant_row(x1[y] - x0[y], vx + i, vy + i, volume + i, min_film_mm,
                         next_stay_.data() + i, next_across_x_.data() + i,
                         next_across_y_.data() + i, next_diagonal_.data() + i);
  }
}

void Advection::use_prepared_quadrant(int sign_x, int sign_y) {
  quadrant_x_ = sign_x < 0 ? -1 : 1;
  quadrant_y_ = sign_y < 0 ? -1 : 1;
  // The three shares live in the east, south and south-east grids whatever the quadrant.
  stay_.swap(next_stay_);
  east_.swap(next_across_x_);
  south_.swap(next_across_y_);
  south_east_.swap(next_diagonal_);
}

void Advection::prepare(int width, int height, const float* vx, const float* vy,
                        const float* volume, float min_film_mm) {
  resize(width, height);
  parallel_rows(height, width,
                [&](int y0, int y1) { prepare_rows(y0, y1, vx, vy, volume, min_film_mm); });
}

void Advection::apply(const float* q, float* out) const {
  apply(&q, &out, 1);
}

void Advection::apply(const float* const* q, float* const* out, int count) const {
  parallel_rows(height_, width_, [&](int y0, int y1) { apply_rows(q, out, count, y0, y1); });
}

void Advection::apply_rows(const float* const* q, float* const* out, int count, int y0,
                           int y1) const {
  for (int y = y0; y < y1; ++y) apply_span(q, out, count, y, 0, width_);
}

void Advection::apply_span(const float* const* q, float* const* out, int count, int y, int x0,
                           int x1) const {
  if (x1 <= x0) return;
  const int width = x1 - x0;
  const std::ptrdiff_t s = width_ + 2;
  const std::ptrdiff_t row = (y + 1) * s + 1 + x0;
  if (quadrant_x_ != 0) {
    // The neighbours behind the motion send: the one a column back, a row back, and both.
    const std::ptrdiff_t from_x = -quadrant_x_, from_y = -quadrant_y_ * s;
    for (int k = 0; k < count; ++k)
      gather_quadrant_row(width, from_x, from_y, q[k] + row, out[k] + row, stay_.data() + row,
                          east_.data() + row, south_.data() + row, south_east_.data() + row);
    return;
  }
  // Shares arriving from each neighbour: the neighbour to the west sends east, etc.
  for (int k = 0; k < count; ++k)
    gather_row(width, s, q[k] + row, out[k] + row, stay_.data() + row, east_.data() + row - 1,
               west_.data() + row + 1, south_.data() + row - s, north_.data() + row + s,
               south_east_.data() + row - s - 1, south_west_.data() + row - s + 1,
               north_east_.data() + row + s - 1, north_west_.data() + row + s + 1);
}

}  // namespace impasto::paintcore
