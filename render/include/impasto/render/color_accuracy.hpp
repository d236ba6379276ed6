#pragma once
// How far an N-node rendering is from the 1-nm full-spectrum one, in CIEDE2000, over a
// fixed set of paint samples (`impasto bench color`, docs/color-accuracy.md).
#include <string>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/render_settings.hpp"

namespace impasto::render {

// The kinds of paint a painting is made of: the classes `bench color` reports apart
// (painting_color_samples; "painting" are cells of replayed paintings, which the command
// renders itself).
inline constexpr const char* kColorClasses[] = {"ground", "masstone", "tint",
                                                "glaze",  "stack",    "painting"};

// One paint sample: a layer of a pigment mix over a ground, and beneath it, for stacks, a
// dry layer of another mix.
struct ColorSample {
  std::string name;
  std::vector<std::pair<int, float>> mix;  // pigment index, concentration (sums to 1)
  float thickness_mm = 0.0f;               // 0 (and no mix): the bare ground
  bool over_black = false;                 // ground: black's R∞ instead of white's
  std::string kind;                        // one of kColorClasses; empty for standard_color_samples
  std::vector<std::pair<int, float>> under_mix;  // the dry layer beneath (stacks)
  float under_mm = 0.0f;
  // Seen as the default renderer shows a flat layer under a uniform sky: the surface's k1 and
  // Saunderson's body term (RenderSettings::saunderson); off, the bare Kubelka-Munk
  // reflectance (standard_color_samples, as docs/color-accuracy.md's older tables).
  bool through_surface = false;
};

// Every pigment as masstone (opaque) and as a tint (1 part to 9 parts White);
// every pair mixed 50/50 (opaque); a thin glaze (0.01 mm) of each over white and over black.
// Throws std::runtime_error when the pigments lack "White" or "Black".
std::vector<ColorSample> standard_color_samples(const std::vector<data::Pigment>& pigments);

// What a painting is made of, seen through the paint's surface as the renderer shows it:
//   ground   the bare canvas ground (White's R∞);
//   masstone every pigment, and every pair 50/50, opaque;
//   tint     every pigment with White 1:1, 1:2, 1:5, 1:10 and 1:20, opaque;
//   glaze    every pigment and every pair 50/50, 0.5 to 50 optical units thick, over the
//            ground and over black;
//   stack    a wet glaze (2 and 10 units) of every pigment over a dry opaque tint 1:2 of
//            every other.
// Throws std::runtime_error when the pigments lack "White" or "Black".
std::vector<ColorSample> painting_color_samples(const std::vector<data::Pigment>& pigments);

// Mean, 95th percentile and maximum ΔE00 of one class of samples.
struct ClassError {
  std::string kind;
  int count = 0;
  double mean_de00 = 0.0, p95_de00 = 0.0, max_de00 = 0.0;
  std::string worst;
};
// The statistics of `errors` (each with the name of its sample); count 0 when empty.
ClassError summarise_errors(std::string kind,
                            const std::vector<std::pair<double, std::string>>& errors);

// A point of the speed/accuracy trade: its cost with the run-to-run spread of that cost, its
// error, and the group it competes in (a light).
struct CostAndError {
  std::string group;
  double ns_per_cell = 0.0, ns_spread = 0.0;
  double error = 0.0;
};
// Which points are on the frontier: no other point of the group is as cheap and more accurate,
// where costs closer than either's spread count as equal (a point is not on the frontier by
// timing noise alone).
std::vector<bool> frontier_points(const std::vector<CostAndError>& points);

struct AccuracyResult {
  int nodes = 0;  // 0: the full spectrum (the reference itself)
  std::string light;
  ReflectanceStorage storage = ReflectanceStorage::float32;
  double mean_de00 = 0.0;
  double max_de00 = 0.0;
  std::string worst_sample;
  double ns_per_cell = 0.0;         // one wet layer of two pigments over a baked substrate, to XYZ
  double ns_per_cell_spread = 0.0;  // the timing runs' max - min: the run-to-run noise
  std::vector<ClassError> classes;  // per kind of sample, in the order they first appear
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
