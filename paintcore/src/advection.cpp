#include "impasto/paintcore/advection.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "parallel_rows.hpp"

namespace impasto::paintcore {

void Advection::prepare(int width, int height, const float* vx, const float* vy,
                        const float* volume, float min_film_mm) {
  width_ = width;
  height_ = height;
  const std::size_t n = padded_size();
  for (auto* grid : {&stay_, &east_, &west_, &south_, &north_, &south_east_, &south_west_,
                     &north_east_, &north_west_})
    grid->assign(n, 0.0f);
  const int stride = width + 2;
  parallel_rows(height, width, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y + 1) * stride + x + 1;
        const float ax = std::abs(vx[i]);
        const float ay = std::abs(vy[i]);
        // The translated column overlaps the neighbours by these areas (Fig. 4, in 2D).
        const float leaving_share = ax + ay - ax * ay;
        float scale = 1.0f;  // of the shares that leave; < 1 keeps the minimum film
        const float q = volume[i];
        if (leaving_share > 0.0f) {
          const float leaving = q * leaving_share;
          if (q <= min_film_mm || leaving <= 0.0f)
            scale = 0.0f;
          else if (q - leaving < min_film_mm)
            scale = (q - min_film_mm) / leaving;
        }
        const float px = std::max(vx[i], 0.0f) * scale;
        const float mx = std::max(-vx[i], 0.0f) * scale;
        const float py = std::max(vy[i], 0.0f);
        const float my = std::max(-vy[i], 0.0f);
        stay_[i] = 1.0f - scale * leaving_share;
        east_[i] = px * (1.0f - ay);
        west_[i] = mx * (1.0f - ay);
        south_[i] = scale * py * (1.0f - ax);
        north_[i] = scale * my * (1.0f - ax);
        south_east_[i] = px * py;
        south_west_[i] = mx * py;
        north_east_[i] = px * my;
        north_west_[i] = mx * my;
      }
  });
}

void Advection::apply(const float* q, float* out) const {
  apply(&q, &out, 1);
}

void Advection::apply(const float* const* q, float* const* out, int count) const {
  parallel_rows(height_, width_, [&](int y0, int y1) { apply_rows(q, out, count, y0, y1); });
}

void Advection::apply_rows(const float* const* q, float* const* out, int count, int y0,
                           int y1) const {
  const std::ptrdiff_t s = width_ + 2;
  for (int y = y0; y < y1; ++y) {
    const std::ptrdiff_t row = (y + 1) * s + 1;
    // Shares arriving from each neighbour: the neighbour to the west sends east, etc.
    const float* from_self = stay_.data() + row;
    const float* from_w = east_.data() + row - 1;
    const float* from_e = west_.data() + row + 1;
    const float* from_n = south_.data() + row - s;
    const float* from_s = north_.data() + row + s;
    const float* from_nw = south_east_.data() + row - s - 1;
    const float* from_ne = south_west_.data() + row - s + 1;
    const float* from_sw = north_east_.data() + row + s - 1;
    const float* from_se = north_west_.data() + row + s + 1;
    for (int k = 0; k < count; ++k) {
      const float* c = q[k] + row;
      float* o = out[k] + row;
      for (int x = 0; x < width_; ++x) {
        // A fixed order of terms: the same sum on any thread.
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
  }
}

}  // namespace impasto::paintcore
