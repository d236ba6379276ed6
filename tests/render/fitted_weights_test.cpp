// Node weights fitted to a palette: white stays exact, the palette's paints come closer.
#include "impasto/render/fitted_weights.hpp"

#include <gtest/gtest.h>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/color_accuracy.hpp"
#include "impasto/render/spectral_palette.hpp"

using namespace impasto;
using namespace impasto::render;

TEST(FittedWeights, KeepNodesAndWhite) {
  const auto& db = data::PigmentDatabase::defaults();
  const std::vector<data::Pigment> pigments{db.get("Titanium White"), db.get("Carbon Black"),
                                            db.get("Diarylide Yellow"),
                                            db.get("Phthalo Blue (Green Shade)")};
  const data::Spectrum light = data::light_from_spec("D65");
  const auto& cmf = data::cie1931_2deg();
  SpectralSampling sampling = make_spectral_sampling(light, cmf, 8);
  const SpectralSampling interpolatory = sampling;
  fit_node_weights(sampling, light, cmf, {}, pigments, hiding_reflectance(pigments[0]), 0.1);
  EXPECT_EQ(sampling.wavelengths_nm, interpolatory.wavelengths_nm);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(sampling.white_xyz[c], interpolatory.white_xyz[c], 1e-4);
  }
  bool changed = false;
  for (std::size_t i = 0; i < sampling.to_xyz.size(); ++i) {
    changed = changed || sampling.to_xyz[i] != interpolatory.to_xyz[i];
  }
  EXPECT_TRUE(changed);
}

TEST(FittedWeights, ReduceErrorOnAFourPigmentPalette) {
  const auto& db = data::PigmentDatabase::defaults();
  const std::vector<data::Pigment> pigments{db.get("Titanium White"), db.get("Carbon Black"),
                                            db.get("Diarylide Yellow"),
                                            db.get("Phthalo Blue (Green Shade)")};
  const data::Spectrum light = data::light_from_spec("D65");
  const auto samples = standard_color_samples(pigments);
  const AccuracyResult plain = evaluate_color_accuracy(light, "D65", 6, pigments, samples);
  const AccuracyResult fitted = evaluate_color_accuracy(
      light, "D65", 6, pigments, samples, ReflectanceStorage::float32, NodeWeights::fitted);
  EXPECT_LT(fitted.mean_de00, plain.mean_de00);
  EXPECT_GT(plain.mean_de00, 0.0);
}
