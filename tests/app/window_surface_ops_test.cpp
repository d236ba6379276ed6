// The window's medium and varnish (docs/window.md), without a window: the Palette panel's
// medium goes into every load the window submits (load_event), the session's recording keeps
// it as `medium=` and the paint laid with it carries it; the Image > Varnish dialog's fields
// become the coat apply_varnish puts on exactly the cells typed, as one undo step.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <impasto/input/stroke_file.hpp>
#include <impasto/paintcore/paint_surface.hpp>
#include <sstream>
#include <string>
#include <variant>

#include "impasto/session/sim_worker.hpp"
#include "window/canvas_menu.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;
using paintcore::Finish;

paintcore::CellSurface surface_at(const paintcore::Painting& p, int x, int y) {
  const paintcore::Canvas& c = p.canvas();
  const int index = c.tile_index(x / paintcore::kTileSize, y / paintcore::kTileSize);
  return paintcore::cell_surface(
      c.tile(index), (y % paintcore::kTileSize) * paintcore::kTileSize + x % paintcore::kTileSize);
}

WindowState burnt_umber_state() {
  WindowState s;
  const auto& pigments = data::PigmentDatabase::defaults().all();
  s.mix_parts.assign(pigments.size(), 0.0f);
  for (std::size_t i = 0; i < pigments.size(); ++i)
    if (pigments[i].name == "Red Oxide") s.mix_parts[i] = 1.0f;
  return s;
}

TEST(WindowSurfaceOps, TheLoadCarriesThePaletteMediumAsAStrokeFileSpellsIt) {
  WindowState s = burnt_umber_state();
  EXPECT_EQ(load_event(s).medium, "") << "no medium chosen: the render settings' decides";
  s.paint_medium = Finish::matte;
  s.paint_medium_amount = 0.3f;  // a float: spelled to the slider's two decimals
  const input::LoadEvent load = load_event(s);
  EXPECT_EQ(load.medium, "matte:0.3");
  const paintcore::Medium medium = paintcore::parse_medium(load.medium);
  EXPECT_EQ(medium.finish, Finish::matte);
  EXPECT_DOUBLE_EQ(medium.amount, 0.3);
  s.paint_medium_amount = 1.0f;
  EXPECT_EQ(load_event(s).medium, "matte") << "the whole medium: its finish alone";
}

TEST(WindowSurfaceOps, PaintLoadedWithAMediumIsRecordedAndLaidWithIt) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_window_medium_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path record = dir / "session.strokes";
  WindowState s = burnt_umber_state();
  s.paint_medium = Finish::matte;
  s.paint_medium_amount = 0.5f;
  {
    paintcore::Painting canvas({64, 48, 100.0, 1}, 1);
    canvas.set_brush({"round", 4.0, 0.5});
    session::SessionRecording recording;
    recording.recorder = std::make_unique<input::StrokeRecorder>(record);
    session::SimWorker worker(std::move(canvas), std::move(recording));
    worker.submit(load_event(s));  // what the Palette panel's Load brush submits
    for (int i = 0; i <= 20; ++i) {
      paintcore::PenSample sample;
      sample.time_s = 0.01 * i;
      sample.x_mm = 2.0 + 0.5 * i;
      sample.y_mm = 6.0;
      sample.pressure = i < 20 ? 0.8f : 0.0f;
      sample.buttons = paintcore::kPenInRange | (i < 20 ? paintcore::kPenTip : 0u);
      worker.submit(input::SampleEvent{sample});
    }
    worker.finish_stroke();
    worker.wait_idle();
    worker.with_painting([&](const paintcore::Painting& p) {
      const int x = static_cast<int>(std::lround(6.0 / 25.4 * 100.0));  // 6 mm in
      const int y = static_cast<int>(std::lround(6.0 / 25.4 * 100.0));
      ASSERT_GT(p.canvas().wet_volume_mm(x, y), 0.0f) << "the stroke laid no paint there";
      const paintcore::CellSurface cell = surface_at(p, x, y);
      EXPECT_GT(cell.medium.share, 0.5f);
      EXPECT_NEAR(cell.medium.log_rms, paintcore::medium_log_rms({Finish::matte, 0.5}), 1e-4);
    });
  }
  bool recorded = false;
  for (const auto& event : input::read_stroke_file(record).events)
    if (const auto* load = std::get_if<input::LoadEvent>(&event))
      recorded = recorded || load->medium == "matte:0.5";
  EXPECT_TRUE(recorded) << "a recovery replays the load without its medium";
  fs::remove_all(dir);
}

// The Image menu's export names its files as `impasto export` does, the solid included; the
// solid it writes is closed and as large as the painting.
TEST(WindowSurfaceOps, TheExportDialogWritesTheReliefAsASolid) {
  ExportChoice choice;
  const fs::path dir = fs::temp_directory_path() / "impasto-export-dialog-test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  choice.stem = (dir / "study").string();
  choice.scale = 2;
  choice.image = false;
  choice.normal = false;
  choice.height_format = 0;
  choice.solid = SolidFormat::kStl;
  choice.solid_options.base_mm = 1.5;
  session::ExportRequest request = export_request(choice);
  ASSERT_EQ(request.solids.size(), 1u);
  EXPECT_EQ(request.solids[0], dir / "study@2x.stl");
  EXPECT_TRUE(request.image.empty());
  EXPECT_EQ(request.solid.base_mm, 1.5);
  choice.solid = SolidFormat::kPly;
  choice.scale = 1;
  choice.image = true;
  EXPECT_EQ(export_request(choice).solids.at(0), dir / "study.ply");
  EXPECT_EQ(export_request(choice).image, dir / "study.png");
  choice.solid = SolidFormat::kNone;
  EXPECT_TRUE(export_request(choice).solids.empty());

  // A binary STL: 84 bytes of header and count, 50 a triangle.
  paintcore::Painting p({40, 30, 100.0, 1}, 1);
  const session::ExportReport report = session::export_painting(p, request);
  ASSERT_GT(report.solid_triangles, 0u);
  EXPECT_EQ(fs::file_size(dir / "study@2x.stl"), 84 + 50 * report.solid_triangles);
  fs::remove_all(dir);
}

TEST(WindowSurfaceOps, TheVarnishDialogCoatsTheTypedCellsAsOneUndoStep) {
  const VarnishRequest whole = varnish_request(Finish::satin, 0.03f, true, {4, 5, 10, 6});
  EXPECT_FALSE(whole.region.has_value()) << "'the whole painting' ignores the typed region";
  // The session records the request as a stroke file's record, to the dialog's decimals.
  EXPECT_EQ(whole.thickness_mm, 0.03);
  {
    input::StrokeFile recorded;
    recorded.events = {input::StrokeEvent{whole}};
    std::ostringstream text;
    input::format_strokes(text, recorded);
    EXPECT_NE(text.str().find("\nvarnish satin 0.03\n"), std::string::npos) << text.str();
  }
  const VarnishRequest part = varnish_request(Finish::gloss, 0.05f, false, {4, 5, 10, 6});
  ASSERT_TRUE(part.region.has_value());
  EXPECT_EQ(*part.region, (paintcore::CellRect{4, 5, 14, 11}));  // x, y, w, h

  paintcore::Painting p({40, 30, 100.0, 1}, 1);
  const std::uint64_t bare = p.state_hash();
  p.apply_varnish(part.finish, part.thickness_mm, part.region);  // as the window applies it
  EXPECT_TRUE(surface_at(p, 4, 5).varnished());
  EXPECT_TRUE(surface_at(p, 13, 10).varnished());
  EXPECT_FALSE(surface_at(p, 14, 10).varnished()) << "w cells wide, no more";
  EXPECT_FALSE(surface_at(p, 13, 11).varnished()) << "h cells high, no more";
  EXPECT_FALSE(surface_at(p, 3, 5).varnished());
  // The coat levels the weave under it (docs/surface.md, "The varnish's relief"): its volume
  // is the typed thickness over the typed cells.
  double coat = 0.0;
  for (int y = 5; y < 11; ++y)
    for (int x = 4; x < 14; ++x) coat += surface_at(p, x, y).varnish_mm;
  EXPECT_NEAR(coat / 60.0, 0.05, 1e-6);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), bare);
}

}  // namespace
}  // namespace impasto::app::window
