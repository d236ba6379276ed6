// Replay tests: whole stroke files through the whole simulation.
#include <gtest/gtest.h>

#include <impasto/input/stroke_file.hpp>
#include <impasto/input/stroke_import.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "impasto/session/replay.hpp"

namespace impasto::session {
namespace {

const std::filesystem::path kDemo =
    std::filesystem::path(IMPASTO_SOURCE_DIR) / "data/strokes/demo.dat";

// canvas + brush == loaded - wiped, for the volume and every pigment, to relative `tolerance`.
void expect_conserved(const paintcore::Painting& painting, double tolerance) {
  const auto canvas = painting.canvas_totals();
  const auto brush = painting.brush_totals();
  const auto loaded = painting.loaded_totals();
  const auto wiped = painting.wiped_totals();
  const double expected_volume = loaded.volume - wiped.volume;
  ASSERT_GT(loaded.volume, 0.0);
  EXPECT_NEAR(canvas.volume + brush.volume, expected_volume, tolerance * loaded.volume);
  for (std::size_t s = 0; s < painting.pigment_slots().size(); ++s) {
    auto at = [s](const paintcore::PaintTotals& t) {
      return s < t.pigment.size() ? t.pigment[s] : 0.0;
    };
    const double expected = at(loaded) - at(wiped);
    EXPECT_NEAR(at(canvas) + at(brush), expected, tolerance * std::max(at(loaded), 1e-12))
        << "pigment slot " << s << " (" << painting.pigment_slots()[s] << ")";
  }
}

input::StrokeFile demo_file() {
  return input::load_strokes_any(kDemo);
}

// A smaller canvas keeps the test quick; the strokes of the demo still fit (at 75 dpi).
ReplayOptions quick_options(int threads) {
  ReplayOptions options;
  options.width_cells = 512;
  options.height_cells = 384;
  options.dpi = 75;
  options.threads = threads;
  options.default_brush.size_mm = 8.0;
  return options;
}

TEST(Replay, DemoConservesPaintAndStaysFinite) {
  ReplayReport report;
  const auto painting = replay(demo_file(), quick_options(0), &report);
  EXPECT_EQ(report.strokes, 30u);
  EXPECT_EQ(report.samples, 2937u);
  EXPECT_GT(painting.steps(), 0u);
  EXPECT_GT(painting.canvas_totals().volume, 0.0);
  EXPECT_EQ(painting.nonfinite_count(), 0u);
  expect_conserved(painting, 1e-5);
}

TEST(Replay, SameHashTwiceAndForAnyThreadCount) {
  const auto file = demo_file();
  const auto one = replay(file, quick_options(1));
  const auto two = replay(file, quick_options(2));
  const auto again = replay(file, quick_options(2));
  EXPECT_EQ(two.state_hash(), again.state_hash());
  EXPECT_EQ(one.state_hash(), two.state_hash());
}

TEST(Replay, SessionEventsDryUndoAndWipeKeepTheLedger) {
  std::istringstream text(R"(impasto-strokes 1
canvas 256 256 100
brush round size=5 stiffness=0.4
load 20 "White" 1 "Blue Red Shade" 2
pen 0.00 10 10 0.6 0 0 0 17
pen 0.05 30 20 0.8 0 0 0 17
pen 0.10 50 30 0.8 0 0 0 17
pen 0.15 50 30 0 0 0 0 16
dry 0.5
load 10 "Cold Yellow" 1
pen 0.20 10 50 0.7 10 -5 30 17
pen 0.25 50 10 0.9 10 -5 30 17
pen 0.30 50 10 0 0 0 0 16
undo
redo
undo
wipe
)");
  const auto file = input::parse_strokes(text, "session.strokes");
  ReplayReport report;
  const auto painting = replay(file, {}, &report);
  EXPECT_EQ(report.strokes, 2u);
  EXPECT_EQ(painting.canvas().width_cells(), 256);
  EXPECT_EQ(painting.canvas().dry_layers().size(), 1u);
  EXPECT_EQ(painting.brush_totals().volume, 0.0);
  EXPECT_EQ(painting.nonfinite_count(), 0u);
  expect_conserved(painting, 1e-5);
}

// The window records a change of quality where it takes it, mid-stroke while it catches up:
// the stroke goes on, the steps after it are the new level's, and a replay told a quality
// steps every stroke at it.
TEST(Replay, AQualityRecordChangesTheStepsMidStroke) {
  std::string text = R"(impasto-strokes 2
canvas 400 300 100
brush round size=20 stiffness=0.5
load 200 "White" 1
)";
  for (int k = 0; k <= 40; ++k) {
    if (k == 20) text += "quality fast\n";
    text += "pen " + std::to_string(0.008 * k) + " " + std::to_string(20 + 1.5 * k) + " 40 " +
            (k < 40 ? "0.7 0 0 0 17\n" : "0 0 0 0 16\n");
  }
  std::istringstream in(text);
  const auto file = input::parse_strokes(in, "quality.strokes");
  ReplayReport report;
  const auto recorded = replay(file, {}, &report);
  EXPECT_EQ(report.strokes, 1u);
  EXPECT_EQ(paintcore::step_quality_of(recorded.params()), paintcore::StepQuality::fast);
  EXPECT_EQ(recorded.nonfinite_count(), 0u);
  expect_conserved(recorded, 1e-5);

  ReplayOptions exact;
  exact.quality = paintcore::StepQuality::exact;
  ReplayReport exact_report;
  const auto reference = replay(file, exact, &exact_report);
  EXPECT_EQ(exact_report.strokes, 1u);
  EXPECT_EQ(paintcore::step_quality_of(reference.params()), paintcore::StepQuality::exact);
  // A 79-cell head: balanced steps it 4.9 cells and fast 9.8, exact a cell at a time.
  EXPECT_GT(reference.steps(), 3 * recorded.steps());
  expect_conserved(reference, 1e-5);
  // The same paint, laid much the same.
  EXPECT_NEAR(recorded.canvas_totals().volume, reference.canvas_totals().volume,
              0.05 * reference.canvas_totals().volume);
}

// A recording at a high dpi that names no brush replays with the default head narrowed to
// what the cells allow (it once failed: "6 mm is 1181 cells at this DPI", naming no line).
// A short, light touch: each step of a head that wide covers the whole 1.5 mm canvas.
TEST(Replay, AFineCanvasNarrowsTheDefaultBrushToFit) {
  std::istringstream text(
      "impasto-strokes 1\ncanvas 300 300 5000\npen 0 0.75 0.75 0.1 0 0 0 1\n"
      "pen 0.01 0.8 0.8 0.1 0 0 0 1\npen 0.02 0.8 0.8 0 0 0 0 0\n");
  const auto file = input::parse_strokes(text, "fine.strokes");
  const paintcore::Painting painting = replay(file, {});
  EXPECT_LE(painting.brush().cells_across(), paintcore::kMaxBrushCells);
  EXPECT_GT(painting.canvas_totals().volume, 0.0);
}

// A brush record's bristle settings replace the head file's, and the painting keeps them (so
// a save reopens with them); a key this version does not know is ignored with a warning.
TEST(Replay, ABrushRecordsBristleSettingsReplaceTheHeadFiles) {
  std::string text = R"(impasto-strokes 2
canvas 300 200 150
brush round size=8 stiffness=0.5 bristle_depth=0 splay=0.05 bristles=200
load 60 "White" 1
)";
  for (int k = 0; k <= 20; ++k)
    text += "pen " + std::to_string(0.008 * k) + " " + std::to_string(10 + 1.5 * k) + " 15 " +
            (k < 20 ? "0.7 0 0 0 17\n" : "0 0 0 0 16\n");
  std::istringstream in(text);
  const auto file = input::parse_strokes(in, "bristles.strokes");
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_NE(file.warnings[0].find("bristles.strokes:3: brush setting 'bristles' is not one"),
            std::string::npos)
      << file.warnings[0];
  const paintcore::Painting painting = replay(file, {});
  const paintcore::BrushHead file_head = paintcore::load_named_brush_head("round");
  ASSERT_GT(file_head.bristles.depth_mm, 0.0) << "the round's head file has bristles";
  EXPECT_EQ(painting.brush().head().bristles.depth_mm, 0.0);
  EXPECT_EQ(painting.brush().head().splay, 0.05);
  EXPECT_EQ(painting.brush().head().bristles.spacing_mm, file_head.bristles.spacing_mm);
  EXPECT_GT(painting.canvas_totals().volume, 0.0);
}

TEST(Replay, UnknownToolNamesTheFileAndLine) {
  std::istringstream text("impasto-strokes 1\ntool trowel\n");
  const auto file = input::parse_strokes(text, "bad.strokes");
  try {
    replay(file, {});
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.strokes:2: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("trowel"), std::string::npos) << e.what();
  }
}

TEST(Replay, UnknownPigmentNamesTheFileLineAndThePigment) {
  std::istringstream text("impasto-strokes 1\nwipe\nload 5 \"Unobtainium Blue\" 1\n");
  const auto file = input::parse_strokes(text, "bad.strokes");
  try {
    replay(file, {});
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.strokes:3: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Unobtainium Blue"), std::string::npos) << e.what();
  }
}

TEST(Replay, StatsCarryTheLedgerAndTheHash) {
  ReplayReport report;
  const auto painting = replay(demo_file(), quick_options(0), &report);
  const auto stats = replay_stats(painting, report);
  for (const char* key :
       {"canvas_volume", "brush_volume", "loaded_volume", "wiped_volume", "pigment_amounts",
        "steps", "cells_updated", "seconds", "nonfinite", "state_hash"}) {
    EXPECT_TRUE(stats.contains(key)) << key;
  }
  const double lhs = stats["canvas_volume"].get<double>() + stats["brush_volume"].get<double>();
  const double rhs = stats["loaded_volume"].get<double>() - stats["wiped_volume"].get<double>();
  EXPECT_NEAR(lhs, rhs, 1e-5 * stats["loaded_volume"].get<double>());
  EXPECT_EQ(stats["state_hash"].get<std::string>().size(), 16u);
}

}  // namespace
}  // namespace impasto::session
