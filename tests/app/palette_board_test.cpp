// The palette board (the model behind the window's panel): paint laid out on it, mixed with
// the brush by the same simulation as the canvas, and picked up as the canvas brush's load.
#include <gtest/gtest.h>

#include <impasto/input/stroke_file.hpp>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <string>

#include "impasto/session/sim_worker.hpp"
#include "window/palette_board.hpp"
#include "window_test_pigments.hpp"

namespace impasto::app::window {
namespace {

using test::kBlue;
using test::kWhite;

paintcore::PenSample pen(double t, double x, double y, bool down) {
  paintcore::PenSample s;
  s.time_s = t;
  s.x_mm = x;
  s.y_mm = y;
  s.pressure = down ? 0.8f : 0.0f;
  s.buttons = paintcore::kPenInRange | (down ? paintcore::kPenTip : 0u);
  return s;
}

// Back and forth through both blobs, as an artist mixes them.
void mix_strokes(PaletteBoard& board) {
  double t = 0.0;
  for (int pass = 0; pass < 3; ++pass) {
    for (int i = 0; i <= 40; ++i) {
      const double x = pass % 2 == 0 ? 15.0 + 0.5 * i : 35.0 - 0.5 * i;
      board.apply(input::SampleEvent{pen(t += 0.01, x, 20.0, true)});
    }
    board.apply(input::SampleEvent{pen(t += 0.01, 20.0, 20.0, false)});
  }
}

PaletteBoard board_with_two_blobs() {
  PaletteBoard board(60.0, 40.0, 100.0);
  board.set_brush({"round", 6.0, 0.5});
  board.lay_out({{kWhite, 1.0}}, 30.0, 18.0, 20.0);
  board.lay_out({{kBlue, 1.0}}, 30.0, 32.0, 20.0);
  return board;
}

TEST(PaletteBoard, LayingOutLeavesPaintOnTheBoardAndACleanBrush) {
  const PaletteBoard board = board_with_two_blobs();
  const paintcore::Painting& p = board.painting();
  EXPECT_EQ(p.canvas().width_cells(), 236);  // 60 mm at 100 dpi
  EXPECT_GT(p.canvas_totals().volume, 1.0);
  EXPECT_EQ(p.brush_totals().volume, 0.0);
  EXPECT_FALSE(board.pick_up().has_value());  // nothing on the brush to pick up
  // Everything loaded is on the board or was wiped off the brush.
  EXPECT_NEAR(p.canvas_totals().volume + p.wiped_totals().volume, 60.0, 1e-5 * 60.0);  // float
  // Both pigments are on the board, each where it was laid out.
  ASSERT_EQ(p.pigment_slots().size(), 2u);
  EXPECT_GT(p.canvas().wet_volume_mm(static_cast<int>(18.0 / p.canvas().cell_mm()), 79), 0.0f);
  EXPECT_GT(p.canvas().wet_volume_mm(static_cast<int>(32.0 / p.canvas().cell_mm()), 79), 0.0f);
}

TEST(PaletteBoard, MixingPicksUpBothPigmentsAndConservesPaint) {
  PaletteBoard board = board_with_two_blobs();
  mix_strokes(board);
  const paintcore::Painting& p = board.painting();
  const auto load = board.pick_up();
  ASSERT_TRUE(load.has_value());
  // What the pick-up offers is exactly what the simulated brush holds.
  EXPECT_DOUBLE_EQ(load->volume_mm3, p.brush_totals().volume);
  ASSERT_EQ(load->mix.size(), 2u) << "the brush should carry both pigments after mixing";
  double parts = 0.0;
  for (const auto& part : load->mix) {
    EXPECT_GT(part.parts, 0.0) << part.pigment;
    parts += part.parts;
  }
  EXPECT_NEAR(parts, load->volume_mm3, 1e-6 * load->volume_mm3);  // pigment parts are volumes
  // Conservation over the whole board: board + brush + wiped = loaded.
  const double kept = p.canvas_totals().volume + p.brush_totals().volume + p.wiped_totals().volume;
  EXPECT_NEAR(kept, p.loaded_totals().volume, 1e-5 * p.loaded_totals().volume);
}

// The window sets the board's brush from its panel every frame, between the samples of a
// scrub: that must not end the stroke (each frame's stroke would lift off and give back
// what it took: "board brush holds 0.0 mm³" after three passes with a real pointer).
TEST(PaletteBoard, MixingWithTheBrushSetEveryFramePicksUpTheSame) {
  PaletteBoard reference = board_with_two_blobs();
  mix_strokes(reference);
  PaletteBoard board = board_with_two_blobs();
  double t = 0.0;
  for (int pass = 0; pass < 3; ++pass) {
    for (int i = 0; i <= 40; ++i) {
      board.set_brush({"round", 6.0, 0.5});  // a frame
      const double x = pass % 2 == 0 ? 15.0 + 0.5 * i : 35.0 - 0.5 * i;
      board.apply(input::SampleEvent{pen(t += 0.01, x, 20.0, true)});
    }
    board.set_brush({"round", 6.0, 0.5});
    board.apply(input::SampleEvent{pen(t += 0.01, 20.0, 20.0, false)});
  }
  ASSERT_TRUE(board.pick_up().has_value());
  EXPECT_EQ(board.painting().state_hash(), reference.painting().state_hash());
}

TEST(PaletteBoard, PickUpLoadsTheCanvasBrushThroughTheRecordedSession) {
  PaletteBoard board = board_with_two_blobs();
  mix_strokes(board);
  const auto load = board.pick_up();
  ASSERT_TRUE(load.has_value());
  const auto dir = std::filesystem::temp_directory_path() /
                   ("impasto_palette_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto record = dir / "session.strokes";
  {
    paintcore::Painting canvas({200, 150, 100.0, 1});
    canvas.set_brush({"round", 6.0, 0.5});
    session::SessionRecording recording;
    recording.recorder = std::make_unique<input::StrokeRecorder>(record);
    session::SimWorker worker(std::move(canvas), std::move(recording));
    // What the window's "Pick up onto brush" submits.
    worker.submit(input::WipeEvent{});
    worker.submit(*load);
    worker.wait_idle();
    worker.with_painting([&](const paintcore::Painting& painting) {
      const auto held = painting.brush_totals();
      EXPECT_NEAR(held.volume, load->volume_mm3, 1e-6 * load->volume_mm3);
      // The same pigment proportions as the board brush held.
      for (const auto& part : load->mix) {
        const auto& slots = painting.pigment_slots();
        const auto slot = std::find(slots.begin(), slots.end(), part.pigment) - slots.begin();
        ASSERT_LT(static_cast<std::size_t>(slot), slots.size());
        EXPECT_NEAR(held.pigment[static_cast<std::size_t>(slot)] / held.volume,
                    part.parts / load->volume_mm3, 1e-5);
      }
    });
  }
  // The session file holds the load, so a replay paints with the same mix.
  const auto file = input::read_stroke_file(record);
  bool found = false;
  for (const auto& event : file.events) {
    if (const auto* l = std::get_if<input::LoadEvent>(&event)) found = found || (*l == *load);
  }
  EXPECT_TRUE(found);
  std::filesystem::remove_all(dir);
}

TEST(PaletteBoard, SavedBesideThePaintingAndLoadedBackIdentical) {
  PaletteBoard board = board_with_two_blobs();
  mix_strokes(board);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("impasto_palette_save_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = PaletteBoard::file_beside(dir / "portrait.impasto");
  EXPECT_EQ(file, dir / "portrait.palette.impasto");
  board.save(file);
  const PaletteBoard loaded = PaletteBoard::load(file);
  EXPECT_EQ(loaded.painting().state_hash(), board.painting().state_hash());
  EXPECT_EQ(loaded.pick_up(), board.pick_up());  // the brush's paint comes back too
  std::filesystem::remove_all(dir);
}

TEST(PaletteBoard, AReplacedBoardIsCleanAndWorks) {
  PaletteBoard board = board_with_two_blobs();
  mix_strokes(board);
  board = PaletteBoard(60.0, 40.0, 100.0);  // "Clean board", or another painting's board
  EXPECT_EQ(board.painting().canvas_totals().volume, 0.0);
  board.set_brush({"round", 6.0, 0.5});
  board.lay_out({{kBlue, 1.0}}, 20.0, 30.0, 20.0);
  EXPECT_GT(board.painting().canvas_totals().volume, 0.1);
}

TEST(PaletteBoard, BadSizesAreClearErrors) {
  EXPECT_THROW(PaletteBoard(std::nan(""), 40.0, 100.0), std::runtime_error);
  EXPECT_THROW(PaletteBoard(60.0, -1.0, 100.0), std::runtime_error);
  EXPECT_THROW(PaletteBoard::load("/nonexistent/board.palette.impasto"), std::runtime_error);
}

}  // namespace
}  // namespace impasto::app::window
