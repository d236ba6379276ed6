// The sparse crack map, the crack brush and PNG crack maps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "impasto/cracks/craquelure.hpp"

namespace impasto::cracks {
namespace {

TEST(CrackMap, WithoutCracksAllocatesNothing) {
  CrackMap map(20000, 15000, 0.05);
  EXPECT_EQ(map.allocated_tiles(), 0u);
  EXPECT_EQ(map.memory_bytes(), 0u);
  map.set(10, 10, CrackCell{});  // clearing an empty cell allocates nothing either
  EXPECT_EQ(map.memory_bytes(), 0u);
  EXPECT_FALSE(map.at(5, 5).has_crack());
  EXPECT_EQ(count_crack_networks(map), 0u);
  int visited = 0;
  map.for_each_crack([&](int, int, const CrackCell&) { ++visited; });
  EXPECT_EQ(visited, 0);
}

TEST(CrackMap, OnlyTilesWithCracksExist) {
  CrackMap map(300, 200, 0.1);
  const CrackCell crack{0.2f, 0.03f, CavityShape::ArcGroove, 2};
  map.set(130, 70, crack);
  EXPECT_EQ(map.allocated_tiles(), 1u);
  EXPECT_TRUE(map.tile_has_cracks(2, 1));
  EXPECT_FALSE(map.tile_has_cracks(0, 0));
  EXPECT_EQ(map.at(130, 70).depth_mm, 0.2f);
  EXPECT_EQ(map.at(130, 70).exposed_layer, 2);
  EXPECT_EQ(map.crack_cells(), 1u);
  // Clearing the last crack of a tile frees it, and the map holds nothing again.
  map.set(130, 70, CrackCell{});
  EXPECT_EQ(map.allocated_tiles(), 0u);
  EXPECT_EQ(map.memory_bytes(), 0u);
}

TEST(CrackMap, BadInputIsRejected) {
  EXPECT_THROW(CrackMap(0, 10, 0.1), std::runtime_error);
  EXPECT_THROW(CrackMap(10, 1 << 20, 0.1), std::runtime_error);
  EXPECT_THROW(CrackMap(10, 10, NAN), std::runtime_error);
  CrackMap map(10, 10, 0.1);
  EXPECT_THROW(map.set(10, 0, CrackCell{0.1f, 0.1f, CavityShape::VGroove, 0}), std::out_of_range);
  EXPECT_THROW(map.set(1, 1, CrackCell{NAN, 0.1f, CavityShape::VGroove, 0}), std::runtime_error);
  EXPECT_THROW(map.set(1, 1, CrackCell{0.1f, 0.0f, CavityShape::VGroove, 0}), std::runtime_error);
}

TEST(CrackBrush, StampsAConnectedLineAlongThePolyline) {
  CrackMap map(200, 200, 0.1);
  CrackStroke stroke;
  stroke.points_mm = {{1.0, 1.0}, {15.0, 9.0}, {18.0, 18.0}};
  stroke.depth_mm = 0.3;
  stroke.half_width_mm = 0.02;
  stamp_crack(map, stroke);
  EXPECT_EQ(count_crack_networks(map), 1u);
  EXPECT_TRUE(map.at(10, 10).has_crack());    // the first point (1 mm, 1 mm)
  EXPECT_TRUE(map.at(179, 179).has_crack());  // the last
  EXPECT_FALSE(map.at(10, 150).has_crack());  // far from the line
  EXPECT_EQ(map.at(150, 90).depth_mm, 0.3f);  // on the first segment
  // A shallower stroke across it does not make the existing crack shallower.
  CrackStroke shallow = stroke;
  shallow.points_mm = {{0.0, 9.0}, {20.0, 9.0}};
  shallow.depth_mm = 0.1;
  stamp_crack(map, shallow);
  EXPECT_EQ(map.at(150, 90).depth_mm, 0.3f);
  EXPECT_EQ(map.at(50, 90).depth_mm, 0.1f);
  CrackStroke bad = stroke;
  bad.points_mm[1][0] = NAN;
  EXPECT_THROW(stamp_crack(map, bad), std::runtime_error);
}

class CrackPng : public ::testing::Test {
 protected:
  std::filesystem::path dir_ =
      std::filesystem::temp_directory_path() /
      ("impasto_cracks_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
       "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { std::filesystem::create_directories(dir_); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
};

TEST_F(CrackPng, RoundTripKeepsDepths) {
  CrackMap map(70, 40, 0.1);
  map.set(3, 4, {0.25f, 0.05f, CavityShape::VGroove, kCanvasGround});
  map.set(69, 39, {0.5f, 0.1f, CavityShape::VGroove, kCanvasGround});
  write_crack_png(map, dir_ / "cracks.png", 0.5);
  CrackImageSettings settings;
  settings.cell_mm = 0.1;
  settings.max_depth_mm = 0.5;
  settings.depth_to_half_width = 5.0;
  const CrackMap back = read_crack_png(dir_ / "cracks.png", settings);
  EXPECT_EQ(back.width(), 70);
  EXPECT_EQ(back.height(), 40);
  EXPECT_EQ(back.crack_cells(), 2u);
  EXPECT_NEAR(back.at(3, 4).depth_mm, 0.25, 1e-5);
  EXPECT_NEAR(back.at(3, 4).half_width_mm, 0.05, 1e-5);
  EXPECT_NEAR(back.at(69, 39).depth_mm, 0.5, 1e-5);
}

TEST_F(CrackPng, MalformedFileNamesTheFile) {
  const auto path = dir_ / "not_a.png";
  std::ofstream(path) << "this is not a PNG";
  try {
    read_crack_png(path, CrackImageSettings{});
    FAIL() << "no error for a malformed PNG";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not_a.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_crack_png(dir_ / "missing.png", CrackImageSettings{}), std::runtime_error);
}

}  // namespace
}  // namespace impasto::cracks
