#pragma once
// The constants of the IMPaSTo paint model (Baxter et al. 2004, section 4). Paint heights
// are in mm (the paper's "units": ~0.001 for a thin painting, ~0.1 for a thick one) and
// velocities in canvas cells per simulation step (1 is the CFL limit).

namespace impasto::paintcore {

struct SimulationParams {
  // Algorithm 1 (brush <-> canvas transfer).
  double xfer_fraction = 0.1;               // share of the source paint moved per step
  double equal_paint_cutoff_mm = 1.0 / 30;  // transfer fades out as |a_b - a_c| -> 0
  double max_xfer_mm = 0.001;               // most paint height moved per cell and step
  double velocity_cutoff_low = 0.2;         // no transfer below this brush speed (cells/step)
  double velocity_cutoff_high = 0.3;        // full transfer above it
  // Paint velocity: v = 1/2 brush velocity - pressure_coeff * grad(penetration), clamped.
  double pressure_coeff = 0.5;  // cells/step per unit slope of the penetration (mm/mm)
  // Adhesion: advection never leaves less than this film (mm) in a cell it takes from.
  double min_film_mm = 0.002;
};

// Throws std::runtime_error naming the field when a parameter is negative or not finite.
void validate(const SimulationParams& params);

}  // namespace impasto::paintcore
