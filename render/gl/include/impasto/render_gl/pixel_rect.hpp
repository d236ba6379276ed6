#pragma once
// A rectangle of a viewport's pixels, as GL counts them.

namespace impasto::render_gl {

// A screen rectangle in GL window pixels (origin bottom-left), [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  long long area() const { return static_cast<long long>(x1 - x0) * (y1 - y0); }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

}  // namespace impasto::render_gl
