// The New painting dialog's sizes: standard sizes and units to cells at a resolution.
#include "window/canvas_size_choice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace impasto::app {
namespace {

TEST(CanvasSizeChoice, A4At150DpiIsTheCellsAPrinterUses) {
  const StandardSize a4 = kStandardSizes[1];
  ASSERT_EQ(a4.name, "A4");
  EXPECT_EQ(cells_across(a4.width_mm, 150.0), 1240);
  EXPECT_EQ(cells_across(a4.height_mm, 150.0), 1754);
}

TEST(CanvasSizeChoice, EveryUnitRoundTripsThroughMillimetres) {
  for (SizeUnit unit : {SizeUnit::cells, SizeUnit::mm, SizeUnit::cm, SizeUnit::in}) {
    EXPECT_NEAR(size_from_mm(size_in_mm(12.5, unit, 300.0), unit, 300.0), 12.5, 1e-12);
  }
  EXPECT_DOUBLE_EQ(size_in_mm(16.0, SizeUnit::in, 150.0), 406.4);
  EXPECT_DOUBLE_EQ(size_in_mm(30.0, SizeUnit::cm, 150.0), 300.0);
  EXPECT_DOUBLE_EQ(size_in_mm(300.0, SizeUnit::cells, 300.0), 25.4);
}

TEST(CanvasSizeChoice, StandardSizesArePortraitAndNamedOnce) {
  for (std::size_t i = 0; i < kStandardSizes.size(); ++i) {
    EXPECT_LE(kStandardSizes[i].width_mm, kStandardSizes[i].height_mm) << kStandardSizes[i].name;
    for (std::size_t j = i + 1; j < kStandardSizes.size(); ++j)
      EXPECT_NE(kStandardSizes[i].name, kStandardSizes[j].name);
  }
}

TEST(CanvasSizeChoice, AbsurdEntriesStayInRangeForTheCheckThatRefusesThem) {
  EXPECT_EQ(cells_across(0.0, 150.0), 1);
  EXPECT_EQ(cells_across(-5.0, 150.0), 1);
  EXPECT_EQ(cells_across(std::numeric_limits<double>::quiet_NaN(), 150.0), 1);
  EXPECT_EQ(cells_across(1e300, 150.0), 1000000000);
}

}  // namespace
}  // namespace impasto::app
