#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/weave.hpp"

namespace impasto::paintcore {
namespace {

TEST(Canvas, TileGridCoversTheCanvasAndStartsEmpty) {
  Canvas canvas(CanvasSpec{100, 70, 300.0, 1});
  EXPECT_EQ(canvas.tiles_x(), 2);
  EXPECT_EQ(canvas.tiles_y(), 2);
  EXPECT_EQ(canvas.allocated_tiles(), 0u);
  EXPECT_EQ(canvas.tile(1, 1), nullptr);
  EXPECT_DOUBLE_EQ(canvas.cell_mm(), 25.4 / 300.0);
  EXPECT_EQ(canvas.wet_volume_mm(99, 69), 0.0f);
  EXPECT_TRUE(canvas.take_changes().empty());
}

TEST(Canvas, RejectsBadSpecsNamingTheField) {
  const auto message = [](CanvasSpec spec) {
    try {
      validate(spec);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({0, 10, 300, 1}).find("width_cells"), std::string::npos);
  EXPECT_NE(message({10, -3, 300, 1}).find("height_cells"), std::string::npos);
  EXPECT_NE(message({10, 10, std::nan(""), 1}).find("dpi"), std::string::npos);
  EXPECT_NE(message({10, 10, 0.0, 1}).find("dpi"), std::string::npos);
  EXPECT_NE(message({kMaxCanvasCells + 1, 10, 300, 1}).find("width_cells"), std::string::npos);
}

TEST(Weave, SeedZeroIsFlat) {
  for (double x : {0.0, 0.13, 7.7}) EXPECT_EQ(canvas_weave_height_mm(0, x, 2.0 * x), 0.0f);
}

TEST(Weave, IsBoundedDeterministicAndVaried) {
  std::set<float> values;
  for (int i = 0; i < 200; ++i) {
    const double x = i * 0.037, y = i * 0.051;
    const float h = canvas_weave_height_mm(7, x, y);
    EXPECT_GE(h, 0.0f);
    EXPECT_LE(h, static_cast<float>(kWeaveAmplitudeMm * 1.2 * 1.0001));
    EXPECT_EQ(h, canvas_weave_height_mm(7, x, y));
    values.insert(h);
  }
  EXPECT_GT(values.size(), 150u);
  // Another seed gives other thread thicknesses.
  EXPECT_NE(canvas_weave_height_mm(7, 0.3, 0.9), canvas_weave_height_mm(8, 0.3, 0.9));
}

TEST(Weave, ThreadEdgesAreLowAndCrossingsHigh) {
  // At a thread boundary in both directions the profiles are zero.
  EXPECT_NEAR(canvas_weave_height_mm(3, 0.0, 0.0), 0.0f, 1e-6);
  // In the middle of a crossing the upper thread is at least 0.8 * 0.775 of the amplitude.
  const float mid = canvas_weave_height_mm(3, 0.5 * kWeaveThreadPitchMm, 0.5 * kWeaveThreadPitchMm);
  EXPECT_GT(mid, 0.8 * 0.775 * kWeaveAmplitudeMm);
}

TEST(Canvas, BaseHeightOfUntouchedTilesComesFromTheWeave) {
  const Canvas canvas(CanvasSpec{64, 64, 254.0, 5});
  const double cell = canvas.cell_mm();
  EXPECT_EQ(canvas.base_height_mm(10, 20), canvas_weave_height_mm(5, 10.5 * cell, 20.5 * cell));
}

}  // namespace
}  // namespace impasto::paintcore
