#pragma once
// How far an N-node rendering is from the 1-nm full-spectrum one, in CIEDE2000, over a
// fixed set of paint samples (`impasto bench color`, docs/color-accuracy.md).
#include <string>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/render_settings.hpp"

namespace impasto::render {

// One paint sample: a single layer of a pigment mix over a ground.
struct ColorSample {
  std::string name;
  std::vector<std::pair<int, float>> mix;  // pigment index, concentration (sums to 1)
  float thickness_mm = 0.0f;
  bool over_black = false;  // ground: black's R∞ instead of white's
};

// Every pigment as masstone (opaque) and as a tint (1 part to 9 parts White);
// every pair mixed 50/50 (opaque); a thin glaze (0.01 mm) of each over white and over black.
// Throws std::runtime_error when the pigments lack "White" or "Black".
std::vector<ColorSample> standard_color_samples(const std::vector<data::Pigment>& pigments);

struct AccuracyResult {
  int nodes = 0;  // 0: the full spectrum (the reference itself)
  std::string light;
  ReflectanceStorage storage = ReflectanceStorage::float32;
  double mean_de00 = 0.0;
  double max_de00 = 0.0;
  std::string worst_sample;
  double ns_per_cell = 0.0;  // one wet layer of two pigments over a baked substrate, to XYZ
};

// ΔE00 of every sample rendered with `nodes` wavelengths against the 1-nm reference, both
// in CIELAB relative to their own white (what the display shows after adaptation). With
// float16 storage the substrate reflectance is rounded to half before compositing, as the
// tile renderer stores it. Timing runs `timing_cells` cells (0: no timing).
AccuracyResult evaluate_color_accuracy(const data::Spectrum& light, const std::string& light_name,
                                       int nodes, const std::vector<data::Pigment>& pigments,
                                       const std::vector<ColorSample>& samples,
                                       ReflectanceStorage storage = ReflectanceStorage::float32,
                                       NodeWeights weights = NodeWeights::interpolatory,
                                       int timing_cells = 0);

}  // namespace impasto::render
