// Crack maps in a painting: conversion to the painting's crack records and back, craquelure
// of a painting's dry layers, the crack brush on a painting, and the file round trip.
#include "impasto/cracks/crack_layer_maps.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <string>

#include "../common/straight_stroke.hpp"

namespace impasto::cracks {
namespace {

using paintcore::kTileSize;

// 200 x 150 cells of 0.1 mm: strokes of thick paint over the left part, dried.
paintcore::Painting half_painted() {
  paintcore::Painting painting({200, 150, 254.0, 0}, 1);
  painting.set_brush({"round", 4.0, 0.5});
  for (int row = 0; row < 4; ++row) {
    painting.load_brush({{"White", 1.0}}, 40.0);
    test::paint_straight_stroke(painting, {1.0, 0.4, 2.0 + 3.5 * row, 20, 0.9f});
  }
  painting.dry(1.0);
  return painting;
}

// The dry film thickness of cell (x, y).
float dry_mm(const paintcore::Painting& painting, int x, int y) {
  const paintcore::Canvas& canvas = painting.canvas();
  const paintcore::DryTile* tile =
      canvas.dry_layers().at(0).find(canvas.tile_index(x / kTileSize, y / kTileSize));
  return tile ? tile->volume_mm[static_cast<std::size_t>((y % kTileSize) * kTileSize +
                                                         x % kTileSize)]
              : 0.0f;
}

TEST(PaintingCracks, MapsConvertToRecordsAndBack) {
  CrackMap map(150, 100, 0.1);
  map.set(3, 4, {0.2f, 0.05f, CavityShape::ConePit, kCanvasGround});
  map.set(149, 99, {0.1f, 0.02f, CavityShape::BoxGroove, 2});
  const paintcore::CrackLayer layer = to_crack_layer(map);
  EXPECT_EQ(layer.allocated_tiles(), 2u);
  EXPECT_EQ(layer.crack_cells(), 2u);
  const paintcore::CrackRecord r = layer.tile(5)->cells[35 * kTileSize + 21];
  EXPECT_EQ(r.depth_mm, 0.1f);
  EXPECT_EQ(r.shape, static_cast<std::uint8_t>(CavityShape::BoxGroove));
  EXPECT_EQ(r.exposed_layer, 2);
  const CrackMap back = to_crack_map(layer, 150, 100, 0.1);
  EXPECT_EQ(back.crack_cells(), 2u);
  EXPECT_EQ(back.at(3, 4).shape, CavityShape::ConePit);
  EXPECT_EQ(back.at(149, 99).half_width_mm, 0.02f);
  EXPECT_TRUE(to_crack_layer(back) == layer);
  EXPECT_TRUE(to_crack_layer(CrackMap(10, 10, 0.1)).empty());
}

TEST(PaintingCracks, CraquelureCracksOnlyTheDryPaint) {
  paintcore::Painting painting = half_painted();
  CraquelureSettings settings;
  settings.island_size_mm = 2.0;
  crack_painting(painting, settings);
  const CrackMap map = crack_map_of(painting);
  EXPECT_GT(map.crack_cells(), 200u);
  map.for_each_crack([&](int x, int y, const CrackCell& cell) {
    EXPECT_GE(dry_mm(painting, x, y), 0.001f);                   // paint there
    EXPECT_LE(cell.depth_mm, dry_mm(painting, x, y) * 1.0001f);  // no deeper than the film
    EXPECT_TRUE(cell.exposed_layer == kCanvasGround || cell.exposed_layer == 0);
  });
  // Same seed, same cracks; the renderer's dirty tiles are the cracked ones.
  paintcore::Painting again = half_painted();
  crack_painting(again, settings);
  EXPECT_TRUE(again.cracks() == painting.cracks());
}

TEST(PaintingCracks, APaintingWithoutDryPaintCannotCrack) {
  paintcore::Painting painting({64, 64, 254.0, 0}, 1);
  try {
    crack_painting(painting, {});
    FAIL() << "cracked a painting without dry paint";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no dry paint"), std::string::npos) << e.what();
  }
}

TEST(PaintingCracks, TheCrackBrushDrawsIntoAPaintingAndTheFileKeepsIt) {
  paintcore::Painting painting = half_painted();
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);
  CrackStroke stroke;
  stroke.points_mm = {{1.0, 1.0}, {15.0, 12.0}};
  stroke.shape = CavityShape::ArcGroove;
  stroke.depth_mm = 0.08;
  stroke.half_width_mm = 0.03;
  stroke.exposed_layer = 0;
  stamp_crack(painting, stroke);
  EXPECT_GT(painting.cracks().crack_cells(), 100u);
  EXPECT_FALSE(painting.take_changes(changes).empty());
  const auto file = std::filesystem::temp_directory_path() /
                    ("impasto_crack_brush_" + std::to_string(::getpid()) + ".impasto");
  painting.save(file);
  const paintcore::Painting loaded = paintcore::Painting::load(file, 1);
  std::filesystem::remove(file);
  EXPECT_TRUE(loaded.cracks() == painting.cracks());
  EXPECT_EQ(crack_map_of(loaded).at(10, 10).shape, CavityShape::ArcGroove);
}

TEST(PaintingCracks, AMapOfAnotherSizeIsRefused) {
  paintcore::Painting painting({64, 64, 254.0, 0}, 1);
  CrackMap map(65, 64, 0.1);
  map.set(1, 1, {0.1f, 0.01f, CavityShape::VGroove, kCanvasGround});
  EXPECT_THROW(set_painting_cracks(painting, map), std::runtime_error);
  CrackMap coarse(64, 64, 0.2);
  EXPECT_THROW(set_painting_cracks(painting, coarse), std::runtime_error);
  // A crack exposing a dry layer the painting lacks.
  CrackMap fits(64, 64, 0.1);
  fits.set(1, 1, {0.1f, 0.01f, CavityShape::VGroove, 0});
  EXPECT_THROW(set_painting_cracks(painting, fits), std::runtime_error);
}

}  // namespace
}  // namespace impasto::cracks
