#pragma once
// How close Gouffé's closed form and its first- and second-order terms come to the Monte
// Carlo reference, over shapes, depth/width ratios and wall reflectances.
#include <string>
#include <vector>

#include "impasto/cracks/monte_carlo.hpp"

namespace impasto::bench {

struct AccuracyRow {
  cracks::CavityShape shape;
  double depth_over_half_width;  // L / R
  // "normal" (a beam along the axis), "diffuse" (a uniform sky) or "scene" (the renderer's
  // default light: a sun scene_zenith_deg from the normal, tilted across grooves, plus a sky of
  // scene_sky_share of the irradiance)
  std::string illumination;
  double rho0;
  double reference, reference_error;  // Monte Carlo value and its standard error
  double gouffe;                      // closed form, F of the deepest element
  double gouffe_first;                // closed form, F averaged over the first reflections
  double first_order, second_order;   // rho0 F and rho0 F + rho0^2 (1-F) G
  double corrected;  // closed form corrected by the measured table of this light (cavity_table)
};

struct AccuracyGrid {
  std::vector<cracks::CavityShape> shapes{cracks::kAllShapes.begin(), cracks::kAllShapes.end()};
  std::vector<double> depth_over_half_width{0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0};
  std::vector<double> rho0{0.05, 0.2, 0.35, 0.5, 0.65, 0.8, 0.95};
  bool normal = true, diffuse = true, scene = true;
  double scene_zenith_deg = 30.0;  // RenderSettings' light elevation of 60 degrees
  double scene_sky_share = 0.25;   // RenderSettings::ambient
  cracks::MonteCarloSettings monte_carlo{};
};

// One row per (shape, L/R, illumination, rho0); one Monte Carlo run per (shape, L/R,
// illumination) serves every rho0 (the scene mixes its sun's run with the diffuse one).
std::vector<AccuracyRow> measure_crack_accuracy(const AccuracyGrid& grid);

}  // namespace impasto::bench
