// The quality levels are settings of the long steps: exact steps a cell at a time, balanced is
// the model's default, fast steps further; every other parameter is kept.
#include <gtest/gtest.h>
#include <impasto/paintcore/step_quality.hpp>

namespace impasto::paintcore {
namespace {

TEST(StepQuality, ExactStepsEveryHeadACellAtATime) {
  const SimulationParams exact = with_step_quality(SimulationParams{}, StepQuality::exact);
  for (const int cells : {1, 40, 64, 256, 1024}) {
    EXPECT_EQ(max_step_cells(exact, cells), 1.0) << cells;
  }
}

TEST(StepQuality, BalancedIsTheModelsOwnAndFastStepsFurther) {
  const SimulationParams defaults;
  const SimulationParams balanced = with_step_quality(defaults, StepQuality::balanced);
  EXPECT_EQ(balanced.long_step_share, defaults.long_step_share);
  EXPECT_EQ(balanced.long_step_from_cells, defaults.long_step_from_cells);
  EXPECT_EQ(balanced.long_step_drag_cells, defaults.long_step_drag_cells);
  EXPECT_EQ(step_quality_of(defaults), StepQuality::balanced);

  const SimulationParams fast = with_step_quality(defaults, StepQuality::fast);
  EXPECT_EQ(max_step_cells(balanced, 256), 16.0);
  EXPECT_EQ(max_step_cells(fast, 256), 32.0);
  // Fast takes long steps from narrower heads too.
  EXPECT_EQ(max_step_cells(balanced, 40), 1.0);
  EXPECT_EQ(max_step_cells(fast, 40), 5.0);
  EXPECT_GT(fast.long_step_drag_cells, balanced.long_step_drag_cells);
}

TEST(StepQuality, KeepsTheRestOfTheModelAndReadsBack) {
  SimulationParams params;
  params.drag = 0.35;
  params.squeeze_mm_s = 2.5;
  for (const auto& entry : kStepQualityNames) {
    const SimulationParams set = with_step_quality(params, entry.value);
    EXPECT_NO_THROW(validate(set)) << entry.name;
    EXPECT_EQ(set.drag, 0.35) << entry.name;
    EXPECT_EQ(set.squeeze_mm_s, 2.5) << entry.name;
    EXPECT_EQ(step_quality_of(set), entry.value) << entry.name;
    // Back to balanced from any level: the model's own long steps again.
    EXPECT_EQ(step_quality_of(with_step_quality(set, StepQuality::balanced)),
              StepQuality::balanced);
  }
  params.long_step_share = 0.2;  // set by hand (--param): no level
  EXPECT_EQ(step_quality_of(params), std::nullopt);
}

}  // namespace
}  // namespace impasto::paintcore
