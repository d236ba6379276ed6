// The colour-accuracy evaluation: the reference against itself is exact, more nodes help.
#include "impasto/render/color_accuracy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/render_settings.hpp"

using namespace impasto;
using namespace impasto::render;

namespace {
std::vector<data::Pigment> three_pigments() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Black"), db.get("Magenta")};
}
}  // namespace

TEST(ColorAccuracy, StandardSamplesCoverMasstonesTintsPairsAndGlazes) {
  const auto samples = standard_color_samples(three_pigments());
  // 3 masstones + 2 tints + 6 glazes + 3 pairs.
  EXPECT_EQ(samples.size(), 14u);
  EXPECT_THROW(standard_color_samples({three_pigments()[2]}), std::runtime_error);
}

TEST(ColorAccuracy, FullSpectrumAgainstItselfIsExactAndNodesConverge) {
  const auto pigments = three_pigments();
  const auto samples = standard_color_samples(pigments);
  const data::Spectrum light = data::light_from_spec("A");
  EXPECT_EQ(evaluate_color_accuracy(light, "A", 0, pigments, samples).max_de00, 0.0);
  const double coarse = evaluate_color_accuracy(light, "A", 3, pigments, samples).mean_de00;
  const double fine = evaluate_color_accuracy(light, "A", 16, pigments, samples).mean_de00;
  EXPECT_GT(coarse, 0.0);
  EXPECT_LT(fine, coarse);
  EXPECT_LT(fine, 1.0);
}

// What paintings are made of: each class, counted; the pigments a sample names exist.
TEST(ColorAccuracy, PaintingSamplesCoverEveryClassAPaintingIsMadeOf) {
  const auto samples = painting_color_samples(three_pigments());
  std::map<std::string, int> count;
  for (const ColorSample& s : samples) {
    ++count[s.kind];
    EXPECT_TRUE(s.through_surface) << s.name;
    for (const auto& [pigment, share] : s.mix) EXPECT_LT(pigment, 3) << s.name;
  }
  EXPECT_EQ(count["ground"], 1);
  EXPECT_EQ(count["masstone"], 3 + 3);         // alone and the pairs
  EXPECT_EQ(count["tint"], 2 * 5);             // each but White, 1:1 to 1:20
  EXPECT_EQ(count["glaze"], (3 + 3) * 7 * 2);  // 7 thicknesses over ground and black
  EXPECT_EQ(count["stack"], 4 * 2);  // wet over a dry tint of another (not White): 4 pairs
  EXPECT_THROW(painting_color_samples({three_pigments()[2]}), std::runtime_error);
}

TEST(ColorAccuracy, ClassesAreSummarisedByMeanP95AndMax) {
  std::vector<std::pair<double, std::string>> errors;
  for (int i = 100; i >= 1; --i) errors.push_back({i, "sample " + std::to_string(i)});
  const ClassError c = summarise_errors("glaze", errors);
  EXPECT_EQ(c.count, 100);
  EXPECT_DOUBLE_EQ(c.mean_de00, 50.5);
  EXPECT_DOUBLE_EQ(c.p95_de00, 95.0);
  EXPECT_DOUBLE_EQ(c.max_de00, 100.0);
  EXPECT_EQ(c.worst, "sample 100");
  EXPECT_EQ(summarise_errors("ground", {}).count, 0);
}

// Each class is exact at the full spectrum and converges with the nodes; the surface (k1 +
// the body) makes a glaze's colour differ from the bare reflectance's.
TEST(ColorAccuracy, EveryClassIsExactAtTheReferenceAndConverges) {
  const auto pigments = three_pigments();
  const auto samples = painting_color_samples(pigments);
  const data::Spectrum light = data::light_from_spec("D65");
  const AccuracyResult exact = evaluate_color_accuracy(light, "D65", 0, pigments, samples);
  EXPECT_EQ(exact.max_de00, 0.0);
  ASSERT_EQ(exact.classes.size(), 5u);  // the painting class is the command's
  const AccuracyResult coarse = evaluate_color_accuracy(light, "D65", 3, pigments, samples);
  const AccuracyResult fine = evaluate_color_accuracy(light, "D65", 16, pigments, samples);
  ASSERT_EQ(fine.classes.size(), 5u);
  for (std::size_t k = 0; k < fine.classes.size(); ++k) {
    EXPECT_LT(fine.classes[k].mean_de00, 0.2) << fine.classes[k].kind;
    EXPECT_LE(fine.classes[k].mean_de00, coarse.classes[k].mean_de00) << fine.classes[k].kind;
    EXPECT_LE(fine.classes[k].p95_de00, fine.classes[k].max_de00);
  }
  EXPECT_GT(coarse.classes[3].mean_de00, 0.0);  // the glazes
}

// The default (its node count and rule) on what paintings are made of, with the bundled
// paints: every class within 0.3 mean and 1.5 max dE00 of the 1 nm reference under a
// daylight, an incandescent and a narrow-band fluorescent light (docs/color-accuracy.md;
// the painted cells of the replays are `impasto bench color`'s).
TEST(ColorAccuracy, TheDefaultHoldsEveryKindOfPaintUnderEveryLight) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  const auto samples = painting_color_samples(pigments);
  const RenderSettings defaults;
  for (const char* light_name : {"D65", "A", "F11"}) {
    const AccuracyResult result = evaluate_color_accuracy(
        data::light_from_spec(light_name), light_name, defaults.wavelengths, pigments, samples,
        ReflectanceStorage::float32, defaults.node_weights);
    ASSERT_EQ(result.classes.size(), 5u);
    for (const ClassError& c : result.classes) {
      EXPECT_LT(c.mean_de00, 0.3) << light_name << " " << c.kind << ": " << c.worst;
      EXPECT_LT(c.max_de00, 1.5) << light_name << " " << c.kind << ": " << c.worst;
    }
  }
}

// In the default rule family the worst class's mean, and the mean over all samples, fall as
// nodes are added.
TEST(ColorAccuracy, ErrorFallsAsNodesAreAdded) {
  const auto& pigments = data::PigmentDatabase::defaults().all();
  const auto samples = painting_color_samples(pigments);
  const data::Spectrum d65 = data::light_from_spec("D65");
  double worst_before = 1e9, mean_before = 1e9;
  for (const int nodes : {4, 8, 12, 16}) {
    const AccuracyResult result =
        evaluate_color_accuracy(d65, "D65", nodes, pigments, samples, ReflectanceStorage::float32,
                                RenderSettings{}.node_weights);
    double worst = 0.0;
    for (const ClassError& c : result.classes) worst = std::max(worst, c.mean_de00);
    EXPECT_LT(worst, worst_before) << nodes << " nodes";
    EXPECT_LT(result.mean_de00, mean_before) << nodes << " nodes";
    worst_before = worst;
    mean_before = result.mean_de00;
  }
}

// A point is on the frontier only by an advantage larger than the timing noise.
TEST(ColorAccuracy, TheFrontierIgnoresTimingNoise) {
  // Two rules of one cost (45 and 47 ns, each +-3 between runs): only the more accurate is on
  // the frontier, whichever timed faster; a cheaper one by more than the spread is too.
  const std::vector<CostAndError> points = {{"D65", 47.0, 3.0, 0.3},
                                            {"D65", 45.0, 3.0, 0.9},
                                            {"D65", 30.0, 1.0, 2.0},
                                            {"A", 45.0, 3.0, 0.9}};
  const std::vector<bool> on = frontier_points(points);
  EXPECT_EQ(on, (std::vector<bool>{true, false, true, true}));
  // Without the spread the faster, worse one would have been a frontier point.
  std::vector<CostAndError> exact = points;
  for (CostAndError& p : exact) p.ns_spread = 0.0;
  EXPECT_TRUE(frontier_points(exact)[1]);
}
