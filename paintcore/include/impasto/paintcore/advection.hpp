#pragma once
// Conservative cell-centred advection (IMPaSTo section 4.1.1, Fig. 4) on a window of cells.
// Each cell's column of paint is translated by its velocity (vx, vy) in cells/step, |v| <= 1,
// so it overlaps its own cell and up to three neighbours; the overlap areas are the shares
// it sends. A cell never gives away so much that less than the minimum film remains
// (adhesion). Each cell GATHERS what its neighbours send it, so rows are independent: the
// result is the same for any number of threads.
//
// Layout: padded row-major grids of (width + 2) x (height + 2) values; the one-cell border is
// outside the window, holds zeros and is never written. Real cell (x, y) is at
// (y + 1) * (width + 2) + x + 1.
#include <cstddef>
#include <vector>

namespace impasto::paintcore {

class Advection {
 public:
  // Computes the shares each cell sends from its velocity and volume. Velocities on the
  // border must be zero.
  void prepare(int width, int height, const float* vx, const float* vy, const float* volume,
               float min_film_mm);
  // out = advected q, for the real cells (out's border is left alone). q is any quantity that
  // moves with the paint (volume, a pigment amount). q and out must not overlap.
  void apply(const float* q, float* out) const;
  // Advects several quantities in one pass: out[i] = advected q[i].
  void apply(const float* const* q, float* const* out, int count) const;

  // The same in pieces, for callers that fuse stages into their own row-parallel loops:
  // resize once, then prepare_rows over all rows, then (after all rows are prepared)
  // apply_rows over all rows.
  void resize(int width, int height);
  void prepare_rows(int y0, int y1, const float* vx, const float* vy, const float* volume,
                    float min_film_mm);
  // The same for a field whose every velocity points into one quadrant: vx has the sign of
  // sign_x or is 0, and vy of sign_y (a brush's drag, say). Only the three shares toward that
  // quadrant can be non-zero, so only they are computed and gathered: the same results,
  // bit for bit, at half the work. These shares are prepared apart from those apply_rows
  // reads, so that one pass may gather with the shares in use while it prepares the next;
  // use_prepared_quadrant (between passes) hands them to apply_rows until it is called again.
  void prepare_quadrant_rows(int y0, int y1, const float* vx, const float* vy, const float* volume,
                             float min_film_mm);
  // prepare_quadrant_rows on row y's cells [x0[y], x1[y]) only: for a gather that reads no
  // other cell's shares (apply_span over spans whose reads those ranges hold).
  void prepare_quadrant_spans(int y0, int y1, const float* vx, const float* vy, const float* volume,
                              float min_film_mm, const int* x0, const int* x1);
  void use_prepared_quadrant(int sign_x, int sign_y);
  void apply_rows(const float* const* q, float* const* out, int count, int y0, int y1) const;
  // apply_rows on row y's cells [x0, x1) only.
  void apply_span(const float* const* q, float* const* out, int count, int y, int x0, int x1) const;

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t padded_size() const {
    return static_cast<std::size_t>(width_ + 2) * static_cast<std::size_t>(height_ + 2);
  }

 private:
  int width_ = 0;
  int height_ = 0;
  int quadrant_x_ = 0, quadrant_y_ = 0;  // the quadrant prepared, or 0, 0: all eight shares
  // Shares sent by each cell (padded grids): to itself and to its 8 neighbours.
  std::vector<float> stay_, east_, west_, south_, north_, south_east_, south_west_, north_east_,
      north_west_;
  // A quadrant's shares being prepared (they become stay_, east_, south_, south_east_).
  std::vector<float> next_stay_, next_across_x_, next_across_y_, next_diagonal_;
};

}  // namespace impasto::paintcore
