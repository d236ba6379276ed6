#include "impasto/paintcore/transfer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::paintcore {
namespace {

TEST(Transfer, DirectionFollowsTheFilmSplit) {
  // The canvas keeps a quarter of the joint film: it gains from a brush holding more than
  // three times its paint and gives to one holding less.
  EXPECT_GT(brush_transfer_amount(0.1, 0.5, 1.0, 0.25), 0.0);
  EXPECT_LT(brush_transfer_amount(0.1, 0.2, 1.0, 0.25), 0.0);
  EXPECT_DOUBLE_EQ(brush_transfer_amount(0.1, 0.3, 1.0, 0.25), 0.0);  // already split
}

TEST(Transfer, FullRelaxationReachesTheSplitExactly) {
  for (const double share : {0.0, 0.25, 0.5, 1.0})
    for (const double a_c : {0.0, 0.3, 2.0})
      for (const double a_b : {0.0, 0.1, 4.0}) {
        const double moved = brush_transfer_amount(a_c, a_b, 1.0, share);
        EXPECT_NEAR(a_c + moved, share * (a_b + a_c), 1e-12);
        // Never more than the source holds.
        EXPECT_LE(std::max(moved, 0.0), share * a_b + 1e-12);
        EXPECT_LE(std::max(-moved, 0.0), (1 - share) * a_c + 1e-12);
      }
}

TEST(Transfer, RelaxationComposesOverDistanceAndTime) {
  const SimulationParams p;
  // Two steps toward a fixed split cover as much as one step of their summed distance and
  // time: the property that makes a stroke independent of how it is cut into steps.
  const double r1 = transfer_relaxation(0.03, 0.002, p);
  const double r2 = transfer_relaxation(0.11, 0.010, p);
  const double both = transfer_relaxation(0.14, 0.012, p);
  EXPECT_NEAR(1.0 - (1.0 - r1) * (1.0 - r2), both, 1e-15);
  EXPECT_DOUBLE_EQ(transfer_relaxation(0.0, 0.0, p), 0.0);
  EXPECT_NEAR(transfer_relaxation(p.transfer_length_mm, 0.0, p), 1.0 - std::exp(-1.0), 1e-15);
  EXPECT_NEAR(transfer_relaxation(0.0, p.transfer_time_s, p), 1.0 - std::exp(-1.0), 1e-15);
  EXPECT_LE(transfer_relaxation(1e9, 1e9, p), 1.0);
}

TEST(Transfer, FloatAndDoubleAgree) {
  EXPECT_NEAR(brush_transfer_amount(0.001f, 0.006f, 0.27f, 0.25f),
              brush_transfer_amount(0.001, 0.006, 0.27, 0.25), 1e-9);
}

TEST(SimulationParams, ValidationNamesTheField) {
  SimulationParams p;
  p.min_film_mm = -1;
  try {
    validate(p);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("min_film_mm"), std::string::npos);
  }
  p = SimulationParams{};
  p.transfer_length_mm = 0.0;  // would divide by zero
  EXPECT_THROW(validate(p), std::runtime_error);
}

TEST(SimulationParams, SetByName) {
  SimulationParams p;
  set_param(p, "deposit_share=0.4");
  EXPECT_DOUBLE_EQ(p.deposit_share, 0.4);
  EXPECT_THROW(set_param(p, "no_such=1"), std::runtime_error);
  EXPECT_THROW(set_param(p, "plough=abc"), std::runtime_error);
  EXPECT_THROW(set_param(p, "plough"), std::runtime_error);
  try {
    set_param(p, "drag=1x");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("drag"), std::string::npos);
  }
}

}  // namespace
}  // namespace impasto::paintcore
