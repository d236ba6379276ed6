// The simulation's parameters in the painting file (docs/painting-format.md): version 7 holds
// the long steps' settings after the model's parameters, older files load with today's
// defaults for them, and a value no painting holds is refused naming the field.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "../common/scratch_folder.hpp"
#include "hostile_paintings.hpp"
#include "older_painting_files.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

// Every long-step setting away from its default, as `impasto replay --param` may set them.
SimulationParams long_steps(double share) {
  SimulationParams params;
  params.deposit_share = 0.4;
  params.long_step_share = share;
  params.long_step_from_cells = 32.0;
  params.long_step_drag_cells = 2.5;
  return params;
}

void expect_params_eq(const SimulationParams& actual, const SimulationParams& expected) {
  for (const NamedParam& named : all_simulation_params())
    EXPECT_EQ(actual.*named.field, expected.*named.field) << named.name;
}

// A 64-cell brush (long steps from 32 cells) paints one stroke.
Painting painted(const SimulationParams& params) {
  Painting p(CanvasSpec{160, 96, 254.0, 2}, 1);
  p.set_params(params);
  p.set_brush(test::round_brush(6.4, 0.5));
  p.load_brush({{"blue", 1.0}}, 12.0);
  test::stroke_line(p, 3.0, 4.0, 12.0, 5.0, 0.8f, 6);
  return p;
}

std::uint32_t version_of(const std::vector<unsigned char>& file_bytes) {
  std::uint32_t version = 0;
  std::memcpy(&version, file_bytes.data() + kPaintingFileMagicBytes, 4);
  return version;
}

class ParamsFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_params_file_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
};

TEST(ParamsFileFields, EachVersionHoldsTheOlderOnesParametersAndTheNewestHoldsThemAll) {
  const auto all = all_simulation_params();
  EXPECT_TRUE(simulation_param_fields(2).empty());
  EXPECT_EQ(simulation_param_fields(kPaintingFileVersion).size(), all.size());
  const auto v6 = simulation_param_fields(6);
  const auto v7 = simulation_param_fields(7);
  ASSERT_EQ(v7.size(), v6.size() + 3);
  for (std::size_t i = 0; i < v7.size(); ++i) {
    EXPECT_EQ(v7[i].name, all[i].name);
    const bool long_step = std::string(v7[i].name).rfind("long_step", 0) == 0;
    EXPECT_EQ(long_step, i >= v6.size()) << v7[i].name;
    EXPECT_EQ(v7[i].file_version, long_step ? 7u : 3u) << v7[i].name;
  }
}

TEST_F(ParamsFileTest, TheLongStepsSettingsRoundTrip) {
  for (const double share : {0.0, 0.25}) {  // 0: one-cell steps
    SCOPED_TRACE(share);
    const Painting p = painted(long_steps(share));
    const auto file = dir_ / "long_steps.impasto";
    p.save(file);
    const auto bytes = test::file_bytes(file);
    EXPECT_EQ(version_of(bytes), kPaintingFileVersion);
    const Painting loaded = Painting::load(file, 1);
    expect_params_eq(loaded.params(), long_steps(share));
    EXPECT_EQ(loaded.state_hash(), p.state_hash());
    const auto again = dir_ / "again.impasto";
    loaded.save(again);
    EXPECT_EQ(test::file_bytes(again), bytes);
  }
}

TEST_F(ParamsFileTest, AReopenedPaintingStepsWithItsOwnLongSteps) {
  Painting p = painted(long_steps(0.25));
  const auto file = dir_ / "reopened.impasto";
  p.save(file);
  Painting loaded = Painting::load(file, 1);
  Painting with_defaults = Painting::load(file, 1);
  with_defaults.set_params(SimulationParams{});
  for (Painting* q : {&p, &loaded, &with_defaults})
    test::stroke_line(*q, 12.0, 8.0, 3.0, 6.0, 0.8f, 6);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  // The same stroke with the default settings paints otherwise: the settings matter here.
  EXPECT_NE(with_defaults.state_hash(), p.state_hash());
}

TEST_F(ParamsFileTest, VersionSixFilesLoadWithTheLongStepsDefaults) {
  const Painting p = painted(long_steps(0.25));
  const auto file = dir_ / "v7.impasto";
  p.save(file);
  const auto v6 = dir_ / "v6.impasto";
  test::write_painting_file(v6, 6, test::as_version_six(test::payload_of(test::file_bytes(file))));
  const Painting loaded = Painting::load(v6, 1);
  SimulationParams expected = long_steps(0.25);
  const SimulationParams defaults;
  expected.long_step_share = defaults.long_step_share;
  expected.long_step_from_cells = defaults.long_step_from_cells;
  expected.long_step_drag_cells = defaults.long_step_drag_cells;
  expect_params_eq(loaded.params(), expected);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  // A version-7 payload labelled 6 does not load (its settings are read as the slot count).
  test::write_painting_file(v6, 6, test::payload_of(test::file_bytes(file)));
  EXPECT_NE(test::load_error(v6), "no error");
}

TEST_F(ParamsFileTest, VersionEightFilesLoadWithTheContactFadesDefault) {
  SimulationParams params = long_steps(0.25);
  params.touch_mm = 0.1;
  const Painting p = painted(params);
  const auto file = dir_ / "v9.impasto";
  p.save(file);
  const auto v8 = dir_ / "v8.impasto";
  test::write_painting_file(
      v8, 8, test::without_params_after(test::payload_of(test::file_bytes(file)), 8));
  const Painting loaded = Painting::load(v8, 1);
  SimulationParams expected = params;
  expected.touch_mm = SimulationParams{}.touch_mm;
  expect_params_eq(loaded.params(), expected);
  EXPECT_EQ(Painting::load(file, 1).params().touch_mm, 0.1);
}

TEST_F(ParamsFileTest, TheCorpusVersionSixPaintingLoadsWithTheLongStepsDefaults) {
  const auto file = std::filesystem::path(IMPASTO_SOURCE_DIR) /
                    "tests/fuzz/corpus/paintings/small_v6_medium_varnish.impasto";
  ASSERT_EQ(version_of(test::file_bytes(file)), 6u);
  const Painting loaded = Painting::load(file, 1);
  const SimulationParams defaults;
  EXPECT_EQ(loaded.params().long_step_share, defaults.long_step_share);
  EXPECT_EQ(loaded.params().long_step_from_cells, defaults.long_step_from_cells);
  EXPECT_EQ(loaded.params().long_step_drag_cells, defaults.long_step_drag_cells);
  // Saved again, it is a version-7 file that keeps them.
  const auto again = dir_ / "again.impasto";
  loaded.save(again);
  EXPECT_EQ(version_of(test::file_bytes(again)), kPaintingFileVersion);
  expect_params_eq(Painting::load(again, 1).params(), loaded.params());
}

TEST_F(ParamsFileTest, ALongStepValueNoPaintingHoldsIsRefusedNamingTheField) {
  const auto good = test::saved_bytes(painted(long_steps(0.25)));
  const auto fields = simulation_param_fields(kPaintingFileVersion);
  const auto file = dir_ / "bad.impasto";
  const auto error_with = [&](const char* name, double value) {
    std::size_t index = 0;
    while (index < fields.size() && std::string(fields[index].name) != name) ++index;
    EXPECT_LT(index, fields.size()) << name;
    auto bytes = good;
    test::patch_payload(bytes, test::kParamsOffset + 8 * index, value);
    test::write_bytes(file, bytes);
    return test::load_error(file);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Bad {
    const char* name;
    double value;
    const char* why;
  };
  for (const Bad& bad : {Bad{"long_step_share", nan, "is not a finite number"},
                         Bad{"long_step_share", 0.75, "must be in [0, 0.5], got 0.75"},
                         Bad{"long_step_share", -0.1, "must be in [0, 0.5]"},
                         Bad{"long_step_from_cells", 0.0, "must be in (0, 1e+06] cells, got 0"},
                         Bad{"long_step_from_cells", inf, "is not a finite number"},
                         Bad{"long_step_drag_cells", 0.5, "must be in [1, 1e+06] cells"},
                         Bad{"long_step_drag_cells", 1e7, "must be in [1, 1e+06] cells"}}) {
    const std::string error = error_with(bad.name, bad.value);
    SCOPED_TRACE(std::string(bad.name) + " = " + std::to_string(bad.value) + ": " + error);
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u);
    EXPECT_NE(error.find(std::string(bad.name) + "'"), std::string::npos);
    EXPECT_NE(error.find(bad.why), std::string::npos);
  }
  // The unedited bytes load.
  test::write_bytes(file, good);
  EXPECT_EQ(test::load_error(file), "no error");
}

}  // namespace
}  // namespace impasto::paintcore
