// `impasto edit` (crop, resize) and `impasto export` (scale, height and normal maps), through
// the registered commands as main() runs them.
#include "impasto/session/canvas_edit.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "command_line.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/relief_maps.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

class CanvasEditCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("impasto_canvas_edit_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    paintcore::Painting p({80, 60, 254.0, 1}, 1);
    p.set_brush(paintcore::BrushSettings{"round", 2.0, 0.5});
    p.load_brush({{"Red Oxide", 1.0}}, 20.0);
    p.begin_stroke();
    for (int i = 0; i < 12; ++i) {
      paintcore::PenSample s;
      s.x_mm = 0.5 + 0.5 * i;
      s.y_mm = 3.0;
      s.pressure = 0.8f;
      s.buttons = paintcore::kPenTip;
      p.stroke_to(s);
    }
    p.end_stroke();
    p.save(painting());
    original_hash_ = p.state_hash();
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path painting() const { return dir_ / "in.impasto"; }
  fs::path file(const std::string& name) const { return dir_ / name; }
  static void run(const std::string& args) { run_command_in_process(args); }

  fs::path dir_;
  std::uint64_t original_hash_ = 0;
};

TEST_F(CanvasEditCommand, VarnishOverARegionIsSavedWithItsUndoAndDriesWithThePaint) {
  run("edit " + painting().string() +
      " --varnish satin --varnish-thickness 0.05 --region 40,10,20,30 --save " +
      file("varnished.impasto").string());
  paintcore::Painting edited = paintcore::Painting::load(file("varnished.impasto"), 1);
  const paintcore::Tile* tile = edited.canvas().tile(0);
  ASSERT_NE(tile, nullptr);
  // Every cell of the region has the coat, wet and satin (its thickness levelled over the
  // stroke's relief), as much varnish in all as an even 0.05 mm coat; none outside it.
  double coat_mm = 0.0;
  for (int y = 10; y < 40; ++y) {
    for (int x = 40; x < 60; ++x) {
      const paintcore::CellSurface in = paintcore::cell_surface(tile, y * 64 + x);
      ASSERT_TRUE(in.varnished()) << x << "," << y;
      EXPECT_FLOAT_EQ(in.varnish_wetness(), 1.0f);
      EXPECT_FLOAT_EQ(in.varnish_log_rms,
                      static_cast<float>(paintcore::finish_log_rms(paintcore::Finish::satin)));
      coat_mm += in.varnish_mm;
    }
  }
  EXPECT_NEAR(coat_mm, 0.05 * 20 * 30, 1e-5 * 0.05 * 20 * 30);
  EXPECT_FALSE(paintcore::cell_surface(tile, 20 * 64 + 39).varnished());
  run("edit " + file("varnished.impasto").string() + " --dry 1 --save " +
      file("dried.impasto").string());
  edited = paintcore::Painting::load(file("dried.impasto"), 1);
  EXPECT_FLOAT_EQ(paintcore::cell_surface(edited.canvas().tile(0), 20 * 64 + 45).varnish_wetness(),
                  0.0f);
  ASSERT_TRUE(edited.undo());  // the drying
  ASSERT_TRUE(edited.undo());  // the varnish
  EXPECT_EQ(edited.state_hash(), original_hash_);
  // Bad requests name their option.
  for (const std::string& bad :
       {std::string(" --varnish satin --region 70,50,20,20"), std::string(" --region 0,0,5,5")}) {
    try {
      run("edit " + painting().string() + bad + " --save " + file("bad.impasto").string());
      ADD_FAILURE() << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("--region"), std::string::npos) << e.what();
    }
  }
}

TEST_F(CanvasEditCommand, CropThenResizeIsSavedWithItsUndo) {
  run("edit " + painting().string() + " --crop 10,5,50,40 --size 70x70 --anchor top-left --save " +
      file("out.impasto").string());
  paintcore::Painting edited = paintcore::Painting::load(file("out.impasto"), 1);
  EXPECT_EQ(edited.canvas().width_cells(), 70);
  EXPECT_EQ(edited.canvas().height_cells(), 70);
  EXPECT_GT(edited.wiped_totals().volume, 0.0);  // the stroke's start was cut away
  // Reopened, two undos give the painting as it was.
  ASSERT_TRUE(edited.undo());
  EXPECT_EQ(edited.canvas().width_cells(), 50);
  ASSERT_TRUE(edited.undo());
  EXPECT_EQ(edited.state_hash(), original_hash_);
}

TEST_F(CanvasEditCommand, BadRequestsAreRefusedByName) {
  const auto error = [&](const std::string& options) -> std::string {
    try {
      run("edit " + painting().string() + " " + options + " --save " + file("x.impasto").string());
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(error("--crop 70,0,20,20").find("--crop"), std::string::npos);
  EXPECT_NE(error("--size 20by20").find("--size"), std::string::npos);
  EXPECT_NE(error("--size 20x20 --anchor middle").find("middle"), std::string::npos);
  EXPECT_NE(error("").find("nothing to change"), std::string::npos);
  EXPECT_FALSE(fs::exists(file("x.impasto")));
}

TEST_F(CanvasEditCommand, ExportWritesTheScaledImageAndTheMaps) {
  run("export " + painting().string() + " --scale 2 -o " + file("x2.png").string() +
      " --height-map " + file("h.png").string() + " --normal-map " + file("n.png").string());
  const render::Image image = render::read_png(file("x2.png"));
  EXPECT_EQ(image.width, 160);
  EXPECT_EQ(image.height, 120);
  const render::HeightGrid heights = render::read_height_map(file("h.png"));
  EXPECT_EQ(heights.width, 160);
  EXPECT_NEAR(heights.cell_mm, 0.05, 1e-12);
  EXPECT_EQ(render::read_png(file("n.png")).width, 160);
  EXPECT_THROW(run("export " + painting().string()), std::runtime_error);
}

// The relief as a solid: a binary STL of the painting's size in mm (80 x 60 cells at 254 dpi,
// 0.1 mm) over the back, and a PLY with colours beside it; one file for two solids is refused.
TEST_F(CanvasEditCommand, ExportWritesTheReliefAsASolid) {
  run("export " + painting().string() + " --stl " + file("s.stl").string() + " --ply " +
      file("s.ply").string() + " --base-mm 1 --relief-scale 2");
  std::ifstream stl(file("s.stl"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(stl)), {});
  ASSERT_GT(bytes.size(), 84u);
  std::uint32_t triangles = 0;
  std::memcpy(&triangles, bytes.data() + 80, 4);
  ASSERT_EQ(bytes.size(), 84u + 50u * triangles);
  float low[3] = {1e9f, 1e9f, 1e9f}, high[3] = {-1e9f, -1e9f, -1e9f};
  for (std::uint32_t t = 0; t < triangles; ++t) {
    for (int v = 0; v < 3; ++v) {
      float p[3];
      std::memcpy(p, bytes.data() + 84 + 50 * t + 12 + 12 * v, 12);
      for (int i = 0; i < 3; ++i) {
        low[i] = std::min(low[i], p[i]);
        high[i] = std::max(high[i], p[i]);
      }
    }
  }
  EXPECT_NEAR(high[0] - low[0], 8.0f, 1e-4f);
  EXPECT_NEAR(high[1] - low[1], 6.0f, 1e-4f);
  EXPECT_NEAR(low[2], -1.0f, 1e-4f) << "the back under a ground at 0";
  EXPECT_GT(high[2], 0.1f) << "the paint stands on it";
  std::ifstream ply(file("s.ply"), std::ios::binary);
  std::string first;
  std::getline(ply, first);
  EXPECT_EQ(first, "ply");
  EXPECT_THROW(run("export " + painting().string() + " --stl " + file("same.stl").string() +
                   " --obj " + file("./same.stl").string()),
               std::runtime_error);
}

// The height and normal maps (or the image) in one file would leave only the last written.
TEST_F(CanvasEditCommand, ExportRefusesOneFileForTwoOutputs) {
  try {
    run("export " + painting().string() + " --height-map " + file("m.png").string() +
        " --normal-map " + file("./m.png").string());
    ADD_FAILURE() << "one file for both maps was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--height-map and --normal-map name the same file"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(file("m.png")));
}

// A stroke file's `varnish` record (the window's Image > Varnish records it) replays to the
// same painting as `impasto edit --varnish` on the painting the strokes before it made.
TEST_F(CanvasEditCommand, AVarnishRecordReplaysAsEditVarnishDoes) {
  const auto write = [&](const std::string& name, const std::string& varnish) {
    std::ofstream out(file(name));
    out << "impasto-strokes 2\ncanvas 80 60 254\nbrush round size=2 stiffness=0.5\n"
           "load 20 \"Red Oxide\" 1\n";
    for (int i = 0; i < 12; ++i)
      out << "pen " << 0.01 * i << " " << 0.5 + 0.5 * i << " 3 " << (i < 11 ? 0.8 : 0.0)
          << " 0 0 0 " << (i < 11 ? 17 : 16) << "\n";
    out << varnish;
    return file(name).string();
  };
  run("replay " + write("plain.strokes", "") + " --save " + file("plain.impasto").string());
  run("edit " + file("plain.impasto").string() +
      " --varnish gloss --varnish-thickness 0.05 --region 40,10,20,30 --save " +
      file("edited.impasto").string());
  run("replay " + write("varnished.strokes", "varnish gloss 0.05 40 10 20 30\n") + " --save " +
      file("replayed.impasto").string());
  paintcore::Painting edited = paintcore::Painting::load(file("edited.impasto"), 1);
  paintcore::Painting replayed = paintcore::Painting::load(file("replayed.impasto"), 1);
  EXPECT_EQ(replayed.state_hash(), edited.state_hash());
  EXPECT_NE(replayed.state_hash(),
            paintcore::Painting::load(file("plain.impasto"), 1).state_hash());
  EXPECT_TRUE(paintcore::cell_surface(replayed.canvas().tile(0), 20 * 64 + 45).varnished());
  // Undone like a stroke.
  ASSERT_TRUE(replayed.undo());
  ASSERT_TRUE(edited.undo());
  EXPECT_EQ(replayed.state_hash(), edited.state_hash());
  EXPECT_FALSE(paintcore::cell_surface(replayed.canvas().tile(0), 20 * 64 + 45).varnished());

  // A region off the canvas: the replay names the file and the line.
  const std::string off = write("off.strokes", "varnish gloss 0.05 100 100 5 5\n");
  try {
    run("replay " + off);
    ADD_FAILURE() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("off.strokes:17:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("region"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impasto::app
