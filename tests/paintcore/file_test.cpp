#include <gtest/gtest.h>

#include <fstream>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

class PaintingFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() /
        ("impasto_paintcore_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static Painting sample() {
    Painting p(CanvasSpec{130, 70, 254.0, 4});
    p.set_brush(BrushSettings{"filbert", 2.0, 0.6});
    p.load_brush({{"red", 1.0}, {"blue", 1.0}}, 5.0);
    test::stroke_line(p, 2.0, 3.0, 12.0, 5.0, 0.8f, 20, 10.0f, 0.0f, 45.0f);
    p.dry(0.3);
    test::stroke_line(p, 2.0, 5.0, 12.0, 3.0, 0.8f);
    return p;
  }

  std::string load_error(const std::filesystem::path& file) {
    try {
      Painting::load(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }

  std::vector<char> read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  void write(const std::filesystem::path& file, const std::vector<char>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }

  std::filesystem::path dir_;
};

TEST_F(PaintingFileTest, SaveThenLoadGivesTheSameState) {
  const Painting p = sample();
  const auto file = dir_ / "a.impasto";
  p.save(file);
  const Painting q = Painting::load(file);
  EXPECT_EQ(q.state_hash(), p.state_hash());
  EXPECT_EQ(q.pigment_slots(), p.pigment_slots());
  EXPECT_EQ(q.steps(), p.steps());
  EXPECT_EQ(q.canvas().dry_layers().size(), 1u);
  EXPECT_EQ(q.brush().head().name, "filbert");
  EXPECT_DOUBLE_EQ(q.loaded_totals().volume, p.loaded_totals().volume);
  // No temporary file is left beside it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

// What can be painted can be saved and opened again: a brush loaded to the most a head holds
// (kMaxPaintHeightMm a cell) reopens, and a load beyond it is refused when it is made, naming
// how much more the head takes, not when the painting is opened (once: a 0.5 mm round took
// 400 mm³ and the saved painting failed to load, "field 'brush.volume' ... above 1000 mm").
TEST_F(PaintingFileTest, ABrushLoadedToItsLimitReopensAndMoreIsRefusedWhenLoaded) {
  Painting p(CanvasSpec{64, 64, 300.0, 1});
  p.set_brush(BrushSettings{"round", 0.5, 0.5});
  const double area = p.canvas().spec().cell_area_mm2();
  const double capacity = static_cast<double>(kMaxPaintHeightMm) * p.brush().covered_cells() * area;
  try {
    p.load_brush({{"red", 1.0}}, 400.0);
    ADD_FAILURE() << "400 mm³ on a 0.5 mm head (" << capacity << " mm³ at most) was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("load_brush: 400 mm³ is more than this head holds"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(p.brush_totals().volume, 0.0) << "a refused load changes nothing";
  p.load_brush({{"red", 1.0}}, 0.999 * capacity);
  EXPECT_THROW(p.load_brush({{"red", 1.0}}, 0.01 * capacity), std::runtime_error);
  const auto file = dir_ / "full.impasto";
  p.save(file);
  const Painting q = Painting::load(file);
  EXPECT_EQ(q.state_hash(), p.state_hash());
}

TEST_F(PaintingFileTest, TheBrushKeepsItsBodyBristlesAndTheParameters) {
  Painting p(test::flat_spec(64, 64), 1);
  SimulationParams params;
  params.deposit_share = 0.4;
  params.lift_share = 0.6;
  p.set_params(params);
  p.set_brush(BrushSettings{"fan", 3.0, 0.5});
  p.load_brush({{"red", 1.0}}, 4.0, PaintBody::fluid);
  const auto file = dir_ / "body.impasto";
  p.save(file);
  const Painting loaded = Painting::load(file, 1);
  EXPECT_EQ(loaded.brush().body(), PaintBody::fluid);
  EXPECT_EQ(loaded.brush().head().bristles, p.brush().head().bristles);
  EXPECT_EQ(loaded.brush().head().splay, p.brush().head().splay);
  EXPECT_EQ(loaded.brush().footprint_mm(), p.brush().footprint_mm());
  EXPECT_EQ(loaded.params().deposit_share, 0.4);
  EXPECT_EQ(loaded.params().lift_share, 0.6);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
}

// The brush's head, bristles and settings are read back as written, in the painting and in
// its undo history (brush_head_file.hpp, shared by both): a loaded painting saves the same
// bytes, a change of head included.
TEST_F(PaintingFileTest, ALoadedPaintingSavesTheSameBytes) {
  Painting p = sample();
  p.set_brush(BrushSettings{"fan", 3.0, 0.4});
  p.load_brush({{"blue", 1.0}}, 3.0);
  test::stroke_line(p, 3.0, 2.0, 10.0, 6.0, 0.7f);
  const auto first = dir_ / "first.impasto";
  const auto second = dir_ / "second.impasto";
  p.save(first);
  const Painting q = Painting::load(first);
  const BrushHead& head = q.brush().head();
  ASSERT_FALSE(head.perturbations.empty());  // the fan's: the records are exercised
  EXPECT_EQ(head.name, p.brush().head().name);
  EXPECT_EQ(head.description, p.brush().head().description);
  EXPECT_EQ(head.rise, p.brush().head().rise);
  EXPECT_EQ(head.perturbations.size(), p.brush().head().perturbations.size());
  EXPECT_EQ(head.perturbations.back().factor, p.brush().head().perturbations.back().factor);
  EXPECT_EQ(head.bristles, p.brush().head().bristles);
  EXPECT_EQ(q.brush().settings().size_mm, 3.0);
  EXPECT_EQ(q.brush().settings().stiffness, 0.4);
  q.save(second);
  EXPECT_EQ(read(first), read(second));
}

TEST_F(PaintingFileTest, LoadedPaintingKeepsPainting) {
  Painting p = sample();
  const auto file = dir_ / "b.impasto";
  p.save(file);
  Painting q = Painting::load(file);
  test::stroke_line(p, 1.0, 1.0, 8.0, 6.0, 0.9f);
  test::stroke_line(q, 1.0, 1.0, 8.0, 6.0, 0.9f);
  EXPECT_EQ(p.state_hash(), q.state_hash());
}

TEST_F(PaintingFileTest, TruncatedFileNamesFileAndField) {
  const auto file = dir_ / "t.impasto";
  Painting p = sample();
  p.set_saved_history_bytes(0);  // the painting alone (saved_history_test: the history)
  p.save(file);
  std::vector<char> bytes = read(file);
  bytes.resize(bytes.size() / 2);
  write(file, bytes);
  const std::string error = load_error(file);
  EXPECT_NE(error.find("t.impasto"), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  bytes.resize(10);
  write(file, bytes);
  EXPECT_NE(load_error(file).find("version"), std::string::npos) << load_error(file);
}

TEST_F(PaintingFileTest, CorruptByteFailsTheChecksum) {
  const auto file = dir_ / "c.impasto";
  Painting p = sample();
  p.set_saved_history_bytes(0);  // the painting alone (saved_history_test: the history)
  p.save(file);
  std::vector<char> bytes = read(file);
  bytes[bytes.size() / 2] ^= 0x10;
  write(file, bytes);
  const std::string error = load_error(file);
  EXPECT_NE(error.find("c.impasto"), std::string::npos);
  EXPECT_NE(error.find("checksum"), std::string::npos) << error;
}

TEST_F(PaintingFileTest, UnknownVersionAndForeignFiles) {
  const auto file = dir_ / "v.impasto";
  sample().save(file);
  std::vector<char> bytes = read(file);
  bytes[8] = 99;  // the version field follows the 8-byte magic
  write(file, bytes);
  EXPECT_NE(load_error(file).find("unknown version 99"), std::string::npos) << load_error(file);
  write(file, {'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd', '!', '!', '!', '!', '!'});
  EXPECT_NE(load_error(file).find("magic"), std::string::npos);
  EXPECT_NE(load_error(dir_ / "missing.impasto").find("cannot open"), std::string::npos);
}

TEST_F(PaintingFileTest, SaveIntoAMissingFolderFailsClearly) {
  try {
    sample().save(dir_ / "no" / "such" / "x.impasto");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.impasto"), std::string::npos);
  }
}

}  // namespace
}  // namespace impasto::paintcore
