#include <gtest/gtest.h>

#include <vector>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "impasto/paintcore/brush.hpp"
#include "impasto/paintcore/brush_head.hpp"

namespace impasto::paintcore {
namespace {

const std::filesystem::path kBrushes = std::filesystem::path(IMPASTO_SOURCE_DIR) / "data/brushes";

std::string parse_error(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_brush_head(in, "test.brush");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(BrushHead, RoundIsAParaboloid) {
  const BrushHead head = load_named_brush_head("round", kBrushes);
  EXPECT_EQ(head.name, "round");
  EXPECT_DOUBLE_EQ(head.field(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(head.height(0, 0), 0.0);
  // height = rise * (u^2 + v^2) inside the unit disc.
  EXPECT_NEAR(head.height(0.5, 0.0), head.rise * 0.25, 1e-12);
  EXPECT_NEAR(head.height(0.3, 0.4), head.rise * 0.25, 1e-12);
  EXPECT_TRUE(head.covers(0.7, 0.7));
  EXPECT_FALSE(head.covers(0.75, 0.75));
}

TEST(BrushHead, PerturbationsAddCubedPositivePart) {
  std::istringstream in("impasto-brush 1\nname t\nbase 0 0 0 0 0 1\nperturb 2  -1 0 0 0 0 0.25\n");
  const BrushHead head = parse_brush_head(in, "t.brush");
  // Q = 0.25 - u^2: at u = 0, F' = 1 + 2 * 0.25^3; beyond |u| = 0.5, Q < 0 adds nothing.
  EXPECT_NEAR(head.field(0.0, 0.3), 1.0 + 2.0 * 0.015625, 1e-12);
  EXPECT_DOUBLE_EQ(head.field(0.8, 0.0), 1.0);
}

TEST(BrushHead, ShippedHeadsLoadAndDiffer) {
  const BrushHead flat = load_named_brush_head("flat", kBrushes);
  const BrushHead filbert = load_named_brush_head("filbert", kBrushes);
  // A flat head is wide along u and thin along v, with square ends.
  EXPECT_TRUE(flat.covers(0.85, 0.0));
  EXPECT_FALSE(flat.covers(0.0, 0.5));
  EXPECT_FALSE(flat.covers(0.99, 0.0));
  EXPECT_TRUE(flat.covers(0.85, 0.15));
  // A filbert's oval tip: narrower toward its ends.
  EXPECT_TRUE(filbert.covers(0.0, 0.35));
  EXPECT_FALSE(filbert.covers(0.8, 0.35));
}

TEST(BrushHead, ErrorsNameFileAndLine) {
  EXPECT_NE(parse_error("").find("test.brush: empty"), std::string::npos);
  EXPECT_NE(parse_error("brush 1\n").find("test.brush:1:"), std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 2\n").find("version"), std::string::npos);
  const std::string bad_number = parse_error("impasto-brush 1\nname x\nbase 1 2 x 0 0 1\n");
  EXPECT_NE(bad_number.find("test.brush:3:"), std::string::npos) << bad_number;
  EXPECT_NE(bad_number.find("'x'"), std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 1\nname x\nbase 1 2\n").find("expects 6 numbers"),
            std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 1\n# c\n\nfoo 1\n").find("test.brush:4: unknown key 'foo'"),
            std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 1\nname x\n").find("missing 'base'"), std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 1\nname x\nbase 0 0 0 0 0 -1\n").find("centre"),
            std::string::npos);
  EXPECT_NE(parse_error("impasto-brush 1\nname x\nbase 0 0 0 0 0 inf\n").find("finite"),
            std::string::npos);
}

TEST(BrushHead, MissingFileAndBadNamesAreClearErrors) {
  try {
    load_named_brush_head("no_such_head", kBrushes);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_head.brush"), std::string::npos);
  }
  EXPECT_THROW(load_named_brush_head("../secret", kBrushes), std::runtime_error);
}

// Head files are read through the bounded reader: a device or a folder is refused by name
// at once (reading /dev/zero would never end).
TEST(BrushHead, DevicesAndFoldersAreRefusedByName) {
  for (const char* path : {"/dev/zero", "/tmp"}) {
    try {
      load_brush_head(path);
      FAIL() << "expected an error for " << path;
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find("not a file"), std::string::npos) << message;
    }
  }
}

TEST(Brush, RasterisesTheHeadAtTheCellSize) {
  BrushSettings settings;
  settings.size_mm = 4.0;
  const Brush brush(load_named_brush_head("round", kBrushes), settings, 0.1, 2);
  EXPECT_EQ(brush.cells_across(), 40);
  EXPECT_EQ(brush.slot_count(), 2);
  const double disc = std::numbers::pi / 4.0 * 40 * 40;
  EXPECT_NEAR(static_cast<double>(brush.covered_cells()), disc, 0.02 * disc);
  // The underside rises towards the rim: rise * (size / 2) * r^2, plus the bristles' relief
  // across u (cell 20's centre lies at u = 0.025, 0.05 mm from the centre line), that relief
  // capped at a tenth of the half width (2 mm).
  const float centre = brush.footprint_mm()[20 * 40 + 20];
  const Bristles& bristles = brush.head().bristles;
  const double relief_scale =
      std::min(1.0, 0.1 * 2.0 / (bristles.depth_mm * (1.0 + bristles.jitter)));
  EXPECT_NEAR(centre,
              0.5 * 2.0 * (0.025 * 0.025 * 2) + relief_scale * brush.head().bristle_height_mm(0.05),
              1e-6);
  EXPECT_GT(brush.footprint_mm()[20 * 40 + 38], brush.footprint_mm()[20 * 40 + 30]);
  // Softer brushes sink deeper at the same pressure.
  settings.stiffness = 0.0;
  const Brush soft(load_named_brush_head("round", kBrushes), settings, 0.1, 0);
  EXPECT_GT(soft.max_depth_mm(), brush.max_depth_mm());
}

// The window offers sizes up to max_brush_size_mm of the canvas's cells: the widest a canvas
// holds is accepted, a hair more is refused naming the cells, and the most any canvas takes is
// kMaxBrushSizeMm (a coarse canvas's cells would hold more).
TEST(Brush, TheWidestSizeOfferedForACanvasIsAccepted) {
  const BrushHead round = load_named_brush_head("round", kBrushes);
  for (const double cell_mm : {25.4 / 1200.0, 25.4 / 300.0, 25.4 / 150.0}) {
    const double widest = max_brush_size_mm(cell_mm);
    ASSERT_LT(widest, kMaxBrushSizeMm);
    EXPECT_EQ(Brush(round, BrushSettings{"round", widest, 0.5}, cell_mm, 0).cells_across(),
              kMaxBrushCells);
    EXPECT_THROW(Brush(round, BrushSettings{"round", widest + cell_mm, 0.5}, cell_mm, 0),
                 std::runtime_error);
  }
  EXPECT_EQ(max_brush_size_mm(25.4), kMaxBrushSizeMm);  // 1 dpi
  EXPECT_NO_THROW(validate(BrushSettings{"round", kMaxBrushSizeMm, 0.5}));
  EXPECT_THROW(validate(BrushSettings{"round", 1.001 * kMaxBrushSizeMm, 0.5}), std::runtime_error);
}

TEST(Brush, CellColumnsBelongToTheBristleAtTheirCentre) {
  // An 8 mm round at 0.1 mm cells: its 0.45 mm columns of bristles, one centred on the head's
  // middle, span 4 or 5 cell columns each, in order across the head; a knife is one plate.
  BrushSettings settings;
  settings.size_mm = 8.0;
  const Brush round(load_named_brush_head("round", kBrushes), settings, 0.1, 0);
  const std::vector<std::uint32_t>& bristle = round.bristle_of_cell_column();
  ASSERT_EQ(bristle.size(), 80u);
  EXPECT_EQ(bristle.front(), 0u);
  EXPECT_EQ(round.bristle_columns(), static_cast<std::size_t>(bristle.back()) + 1);
  // 4 mm either side of the middle column's 0.225 mm: 8.5 spacings, 9 columns a side.
  EXPECT_EQ(round.bristle_columns(), 19u);
  for (std::size_t i = 0; i < bristle.size(); ++i) {
    const double u_mm = (static_cast<double>(i) + 0.5) * 0.1 - 4.0;
    EXPECT_EQ(static_cast<long>(bristle[i]) - static_cast<long>(bristle[39]),
              round.head().bristle_column(u_mm) - round.head().bristle_column(-0.05))
        << i;
    if (i > 0) {
      EXPECT_LE(bristle[i] - bristle[i - 1], 1u);
    }
  }
  const Brush knife(load_named_brush_head("knife", kBrushes), settings, 0.1, 0);
  EXPECT_EQ(knife.bristle_columns(), 1u);
}

TEST(Brush, FurrowsFinerThanTheGridFade) {
  // The bristles' relief stays whole down to 4 cells a column and fades to nothing at 2 (the
  // Nyquist limit): a round's 0.45 mm columns at 150 dpi are 2.66 cells and keep a third.
  BrushSettings settings;
  settings.size_mm = 8.0;
  const BrushHead head = load_named_brush_head("round", kBrushes);
  BrushHead smooth = head;
  smooth.bristles = {};
  // The bristles' relief: the footprint less the smooth head's, its range across the middle row.
  const auto relief = [&](double cell_mm) {
    const Brush brush(head, settings, cell_mm, 0), plain(smooth, settings, cell_mm, 0);
    const int n = brush.cells_across();
    double most = -1e9, least = 1e9;
    for (int i = n / 4; i < 3 * n / 4; ++i) {
      const std::size_t k = static_cast<std::size_t>(n / 2) * n + i;
      const double h = brush.footprint_mm()[k] - plain.footprint_mm()[k];
      most = std::max(most, h);
      least = std::min(least, h);
    }
    return most - least;
  };
  const double whole = relief(0.45 / 4.5);
  EXPECT_GT(relief(0.45 / 4.0), 0.7 * whole);
  EXPECT_GT(relief(0.45 / 2.66), 0.15 * whole);
  EXPECT_LT(relief(0.45 / 2.66), 0.5 * whole);
  EXPECT_LT(relief(0.45 / 1.9), 0.01 * whole);
}

TEST(Brush, RejectsAbsurdSettings) {
  const BrushHead head = load_named_brush_head("round", kBrushes);
  BrushSettings settings;
  settings.size_mm = std::nan("");
  EXPECT_THROW(Brush(head, settings, 0.1, 0), std::runtime_error);
  settings.size_mm = 200.0;  // 2000 cells at 0.1 mm
  EXPECT_THROW(Brush(head, settings, 0.1, 0), std::runtime_error);
  settings.size_mm = 2.0;
  settings.stiffness = 1.5;
  EXPECT_THROW(Brush(head, settings, 0.1, 0), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
