#include "window/canvas_size_choice.hpp"

#include <algorithm>
#include <cmath>

#include <impasto/paintcore/canvas.hpp>

namespace impasto::app {

double size_in_mm(double value, SizeUnit unit, double dpi) {
  switch (unit) {
    case SizeUnit::cells:
      return value * paintcore::kMmPerInch / dpi;
    case SizeUnit::mm:
      return value;
    case SizeUnit::cm:
      return 10.0 * value;
    case SizeUnit::in:
      return paintcore::kMmPerInch * value;
  }
  return value;
}

double size_from_mm(double mm, SizeUnit unit, double dpi) {
  switch (unit) {
    case SizeUnit::cells:
      return mm * dpi / paintcore::kMmPerInch;
    case SizeUnit::mm:
      return mm;
    case SizeUnit::cm:
      return mm / 10.0;
    case SizeUnit::in:
      return mm / paintcore::kMmPerInch;
  }
  return mm;
}

int cells_across(double mm, double dpi) {
  const double cells = std::round(mm * dpi / paintcore::kMmPerInch);
  // (Clamped before the cast: an absurd entry must not overflow; validate() refuses it.)
  return static_cast<int>(std::clamp(std::isfinite(cells) ? cells : 1.0, 1.0, 1e9));
}

}  // namespace impasto::app
