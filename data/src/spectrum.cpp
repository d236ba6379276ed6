#include "impasto/data/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::data {

double Spectrum::at(double nm) const {
  if (wavelengths_nm.empty() || !(nm >= wavelengths_nm.front()) || nm > wavelengths_nm.back()) {
    return 0.0;
  }
  // First sample strictly above nm; nm lies in [upper - 1, upper).
  const auto upper = std::upper_bound(wavelengths_nm.begin(), wavelengths_nm.end(), nm);
  if (upper == wavelengths_nm.end()) return values.back();  // nm == back()
  const auto i = static_cast<std::size_t>(upper - wavelengths_nm.begin());
  const double x0 = wavelengths_nm[i - 1];
  const double x1 = wavelengths_nm[i];
  const double t = (nm - x0) / (x1 - x0);
  return values[i - 1] + t * (values[i] - values[i - 1]);
}

Spectrum Spectrum::resampled(const std::vector<double>& grid_nm) const {
  Spectrum out{name, grid_nm, std::vector<double>(grid_nm.size())};
  for (std::size_t i = 0; i < grid_nm.size(); ++i) out.values[i] = at(grid_nm[i]);
  return out;
}

std::vector<double> wavelength_grid(double first_nm, double last_nm, double step_nm) {
  if (!std::isfinite(first_nm) || !std::isfinite(last_nm) || !std::isfinite(step_nm) ||
      step_nm <= 0.0 || last_nm < first_nm) {
    throw std::runtime_error("wavelength_grid: need finite first <= last and step > 0, got " +
                             std::to_string(first_nm) + ".." + std::to_string(last_nm) + " step " +
                             std::to_string(step_nm) + " nm");
  }
  // A small tolerance keeps `last` when (last - first) / step is an integer up to rounding.
  const double span = (last_nm - first_nm) / step_nm;
  if (span > 1e7) throw std::runtime_error("wavelength_grid: more than 10 million samples");
  const auto count = static_cast<std::size_t>(std::floor(span + 1e-9)) + 1;
  std::vector<double> grid(count);
  for (std::size_t i = 0; i < count; ++i) grid[i] = first_nm + static_cast<double>(i) * step_nm;
  return grid;
}

}  // namespace impasto::data
