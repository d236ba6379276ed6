// The undo history kept in the painting file (version 5): undo after reopening continues where
// the session left off, the size cap drops the oldest steps, and a damaged history costs only
// itself.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "../common/scratch_folder.hpp"
#include "hasher.hpp"
#include "impasto/paintcore/canvas_reframe.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "painting_file_sections.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::round_brush;
using test::stroke_line;

class SavedHistory : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_history_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A session of every kind of step: load, strokes, a drying, a crop, a stroke after it.
  static Painting session() {
    Painting p(CanvasSpec{150, 110, 254.0, 7}, 1);
    p.set_brush(round_brush(3.0));
    p.load_brush({{"red", 1.0}}, 30.0);
    stroke_line(p, 1.0, 1.0, 12.0, 9.0, 0.8f);
    p.dry(0.4);
    p.load_brush({{"blue", 2.0}, {"red", 1.0}}, 30.0);
    stroke_line(p, 12.0, 1.0, 1.0, 9.0, 0.9f);
    p.reframe_canvas(crop_frame(11, 7, 120, 90));
    stroke_line(p, 2.0, 2.0, 9.0, 7.0, 0.9f);
    return p;
  }

  static std::vector<unsigned char> read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  static void write(const std::filesystem::path& file, const std::vector<unsigned char>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  }
  // The history section of a saved file, decompressed, and the file again around an edited
  // one (sizes and checksums valid: a crafted file, not a damaged one).
  static std::vector<unsigned char> history_of(const std::vector<unsigned char>& bytes) {
    return test::sections_of(bytes).history.value();
  }
  static std::vector<unsigned char> with_history(const std::vector<unsigned char>& bytes,
                                                 const std::vector<unsigned char>& history) {
    test::FileSections sections = test::sections_of(bytes);
    sections.history = history;
    return test::file_of(sections);
  }
  // Where the history section begins in the file (its stored size), after the payload's
  // sizes, compressed bytes and checksum.
  static std::size_t history_offset(const std::vector<unsigned char>& bytes) {
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + kPaintingFileMagicBytes + 4, 8);
    return kPaintingFileMagicBytes + 4 + 16 + stored + 8;
  }
  // Puts a valid checksum on the history's edited compressed bytes.
  static void rehash_stored_history(std::vector<unsigned char>& bytes) {
    const std::size_t at = history_offset(bytes);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + at, 8);
    StreamHasher h;
    h.bytes(bytes.data() + at + 16, stored);
    const std::uint64_t digest = h.digest();
    std::memcpy(bytes.data() + at + 16 + stored, &digest, 8);
  }

  std::filesystem::path dir_;
};

TEST_F(SavedHistory, UndoAfterReopeningGivesTheSameStatesAsWithoutSaving) {
  Painting kept = session();
  kept.undo();  // one step waits to be redone
  const auto file = dir_ / "session.impasto";
  kept.save(file);
  Painting reopened = Painting::load(file, 1);
  EXPECT_EQ(reopened.load_warning(), "");
  ASSERT_EQ(reopened.state_hash(), kept.state_hash());
  ASSERT_EQ(reopened.undo_depth(), kept.undo_depth());
  ASSERT_EQ(reopened.redo_depth(), 1u);
  ASSERT_TRUE(reopened.redo());
  ASSERT_TRUE(kept.redo());
  EXPECT_EQ(reopened.state_hash(), kept.state_hash());
  // Back through the stroke after the crop, the crop, the strokes, the drying, the loads.
  while (kept.undo()) {
    ASSERT_TRUE(reopened.undo());
    ASSERT_EQ(reopened.state_hash(), kept.state_hash()) << "undo depth " << kept.undo_depth();
    EXPECT_EQ(reopened.canvas().width_cells(), kept.canvas().width_cells());
  }
  EXPECT_FALSE(reopened.undo());
  // Loaded without its history (a render needs none): the same painting, nothing to undo.
  const Painting bare = Painting::load(file, 1, false);
  EXPECT_EQ(bare.undo_depth(), 0u);
  EXPECT_EQ(bare.redo_depth(), 0u);
  EXPECT_EQ(bare.state_hash(), Painting::load(file, 1).state_hash());
  while (kept.redo()) {
    ASSERT_TRUE(reopened.redo());
    ASSERT_EQ(reopened.state_hash(), kept.state_hash()) << "redo depth " << kept.redo_depth();
  }
  // Painting on after the reopened history still balances and undoes.
  stroke_line(reopened, 3.0, 8.0, 9.0, 2.0, 0.8f);
  EXPECT_NEAR(test::present_totals(reopened).volume, test::expected_totals(reopened).volume,
              1e-6 * test::expected_totals(reopened).volume);
  ASSERT_TRUE(reopened.undo());
  EXPECT_EQ(reopened.state_hash(), kept.state_hash());
}

TEST_F(SavedHistory, TheCapKeepsTheNewestStepsAndZeroKeepsNone) {
  Painting p = session();
  const auto file = dir_ / "capped.impasto";
  p.set_saved_history_bytes(0);
  p.save(file);
  EXPECT_EQ(Painting::load(file, 1).undo_depth(), 0u);
  const std::uintmax_t without = std::filesystem::file_size(file);
  p.set_saved_history_bytes(std::size_t{64} << 20);
  p.save(file);
  EXPECT_GT(std::filesystem::file_size(file), without);
  // Room for little more than the newest stroke: that step is the one kept.
  p.set_saved_history_bytes(p.undo_bytes() / 4);
  p.save(file);
  Painting capped = Painting::load(file, 1);
  ASSERT_GE(capped.undo_depth(), 1u);
  ASSERT_LT(capped.undo_depth(), p.undo_depth());
  ASSERT_TRUE(capped.undo());
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(capped.state_hash(), p.state_hash());
}

TEST_F(SavedHistory, ADamagedHistoryIsDroppedAndThePaintingKept) {
  Painting p = session();
  const auto file = dir_ / "damaged.impasto";
  p.save(file);
  std::vector<unsigned char> bytes = read(file);
  bytes[history_offset(bytes) + 40] ^= 0x5a;  // inside the history: its checksum fails
  write(file, bytes);
  Painting loaded = Painting::load(file, 1);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  EXPECT_EQ(loaded.undo_depth(), 0u);
  EXPECT_NE(loaded.load_warning().find("damaged.impasto"), std::string::npos);
  EXPECT_NE(loaded.load_warning().find("history_checksum"), std::string::npos)
      << loaded.load_warning();
}

TEST_F(SavedHistory, ACraftedStepIsRefusedByField) {
  Painting p = session();
  const auto file = dir_ / "crafted.impasto";
  p.save(file);
  const std::vector<unsigned char> saved = read(file);
  std::vector<unsigned char> history = history_of(saved);
  // The newest step's dry_layer_count (after the two step counts): 1000 layers that undo would
  // erase from a painting of one.
  const std::uint32_t layers = 1000;
  std::memcpy(history.data() + 16, &layers, 4);
  write(file, with_history(saved, history));
  Painting loaded = Painting::load(file, 1);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  EXPECT_EQ(loaded.undo_depth(), 0u);
  EXPECT_NE(loaded.load_warning().find("history.undo[0].dry_layer_count"), std::string::npos)
      << loaded.load_warning();
  // A step count far beyond the section is refused before anything is allocated for it.
  const std::uint64_t huge = std::uint64_t{1} << 60;
  std::memcpy(history.data(), &huge, 8);
  write(file, with_history(saved, history));
  EXPECT_NE(Painting::load(file, 1).load_warning().find("history.undo_count"), std::string::npos);
}

TEST_F(SavedHistory, MutatedHistoriesLoadOrAreDroppedNeverCrash) {
  // Bytes of the section changed (with its checksum made to match, so that they reach the
  // fields) or cut short, before compression (the fields) or after it (the compressed bytes):
  // every load keeps the painting, with or without a history that then undoes without fault.
  // Under the sanitizer build this is where a bad read would show.
  Painting p = session();
  const auto file = dir_ / "mutated.impasto";
  p.save(file);
  const std::vector<unsigned char> good = read(file);
  const std::vector<unsigned char> history = history_of(good);
  const std::size_t at = history_offset(good);
  std::uint64_t stored = 0;
  std::memcpy(&stored, good.data() + at, 8);
  std::uint64_t state = 12345;
  const auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 33;
  };
  for (int k = 0; k < 80; ++k) {
    std::vector<unsigned char> bytes;
    if (k % 4 == 3) {  // compressed bytes changed
      bytes = good;
      for (int m = 0; m < 1 + k % 3; ++m)
        bytes[at + 16 + next() % stored] ^= static_cast<unsigned char>(1u << (next() % 8));
      rehash_stored_history(bytes);
    } else if (k % 6 == 5) {  // cut short
      std::vector<unsigned char> cut = history;
      cut.resize(next() % history.size());
      bytes = with_history(good, cut);
    } else {  // a few bytes changed, most near the start where the counts are
      std::vector<unsigned char> changed = history;
      for (int m = 0; m < 1 + k % 3; ++m) {
        const std::uint64_t span =
            k % 2 ? changed.size() : std::min<std::uint64_t>(changed.size(), 600);
        changed[next() % span] ^= static_cast<unsigned char>(1u << (next() % 8));
      }
      bytes = with_history(good, changed);
    }
    write(file, bytes);
    Painting loaded = Painting::load(file, 1);
    ASSERT_EQ(loaded.state_hash(), p.state_hash()) << "mutation " << k;
    for (int undo = 0; undo < 3 && loaded.undo(); ++undo)
      ASSERT_EQ(loaded.nonfinite_count(), 0u) << "mutation " << k;
    while (loaded.redo()) {
    }
  }
}

TEST_F(SavedHistory, ACroppedCanvasKeepsItsClothThroughASave) {
  Painting p = session();
  p.set_saved_history_bytes(0);
  const auto file = dir_ / "cloth.impasto";
  p.save(file);
  const Painting loaded = Painting::load(file, 1);
  EXPECT_EQ(loaded.canvas().spec().weave_origin_x_cells, 11);
  EXPECT_EQ(loaded.canvas().spec().weave_origin_y_cells, 7);
  for (int y = 0; y < 90; y += 13)
    for (int x = 0; x < 120; x += 11)
      ASSERT_EQ(loaded.canvas().base_height_mm(x, y), p.canvas().base_height_mm(x, y));
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
}

}  // namespace
}  // namespace impasto::paintcore
