// The colour-accuracy evaluation: the reference against itself is exact, more nodes help.
#include "impasto/render/color_accuracy.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"

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
