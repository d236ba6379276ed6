#include "impasto/paintcore/simulation_params.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::paintcore {

void validate(const SimulationParams& p) {
  const auto check = [](double value, const char* field, bool positive) {
    if (!std::isfinite(value) || value < 0.0 || (positive && value == 0.0))
      throw std::runtime_error(std::string("simulation params: field '") + field + "' must be " +
                               (positive ? "positive" : "non-negative") + " and finite, got " +
                               std::to_string(value));
  };
  check(p.xfer_fraction, "xfer_fraction", false);
  if (p.xfer_fraction > 1.0)
    throw std::runtime_error("simulation params: field 'xfer_fraction' must be <= 1");
  check(p.equal_paint_cutoff_mm, "equal_paint_cutoff_mm", true);
  check(p.max_xfer_mm, "max_xfer_mm", false);
  check(p.velocity_cutoff_low, "velocity_cutoff_low", false);
  check(p.velocity_cutoff_high, "velocity_cutoff_high", false);
  if (p.velocity_cutoff_high <= p.velocity_cutoff_low)
    throw std::runtime_error(
        "simulation params: field 'velocity_cutoff_high' must exceed 'velocity_cutoff_low'");
  check(p.pressure_coeff, "pressure_coeff", false);
  check(p.min_film_mm, "min_film_mm", false);
}

}  // namespace impasto::paintcore
