#pragma once
// Sampled spectra: the currency between data/ (files, CIE tables, pigments) and render/.
#include <string>
#include <vector>

namespace impasto::data {

// A function of wavelength sampled at increasing wavelengths (nm). Between samples it is
// linear; outside them it is zero unless stated otherwise by the producer.
struct Spectrum {
  std::string name;
  std::vector<double> wavelengths_nm;  // strictly increasing
  std::vector<double> values;          // same length as wavelengths_nm

  // Linear interpolation; 0 outside [front, back].
  double at(double nm) const;
  // The spectrum on another wavelength grid (linear interpolation, 0 outside).
  Spectrum resampled(const std::vector<double>& grid_nm) const;
};

// The CIE 1931 2° colour-matching functions x̄, ȳ, z̄ on one shared grid.
struct ColorMatchingFunctions {
  Spectrum x, y, z;
};

// Evenly spaced grid [first, last] with step (all nm); last included when it falls on a step.
std::vector<double> wavelength_grid(double first_nm, double last_nm, double step_nm);

}  // namespace impasto::data
