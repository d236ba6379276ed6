// Big sparse paintings through the painting file: the round trip is exact on any thread count,
// a huge canvas costs only its painted tiles, and a bad tile in any batch of the parallel
// reader is reported first in file order, never as a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <limits>

#include "../common/scratch_folder.hpp"
#include "hasher.hpp"
#include "impasto/paintcore/synthetic_painting.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "painting_file_sections.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

const std::vector<std::string> kSlots{"red", "blue", "white", "umber"};

class BigPaintingFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_big_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A 20000 x 20000 canvas (97,969 tiles) with `painted` of them painted, four slots and a
  // dry layer: 90 tiles are two batches of the parallel reader (85 tiles of four slots each).
  static Painting big(int painted) {
    SyntheticPaintingSpec spec;
    spec.width_cells = spec.height_cells = 20000;
    spec.painted_share = painted / (313.0 * 313.0);
    spec.slots = kSlots;
    return synthetic_painting(spec, 2);
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
  // Where wet tile k's record begins in the payload: after the tiles.count field, which the
  // synthetic painting's first record follows (its index, then dry heights of 0.04 mm).
  static std::size_t tile_offset(const std::vector<unsigned char>& bytes, std::uint32_t count,
                                 int k) {
    const float dry = 0.04f;
    for (std::size_t at = 0; at + 12 < bytes.size(); ++at) {
      std::uint32_t n = 0, index = 1;
      float first_dry = 0;
      std::memcpy(&n, bytes.data() + at, 4);
      std::memcpy(&index, bytes.data() + at + 4, 4);
      std::memcpy(&first_dry, bytes.data() + at + 8, 4);
      if (n == count && index == 0 && first_dry == dry)
        return at + 4 + static_cast<std::size_t>(k) * painting_file_wet_tile_bytes(4);
    }
    ADD_FAILURE() << "no tiles.count field found";
    return 0;
  }
  // A file around an edited payload, its sizes and checksum valid (a crafted file, not a
  // damaged one).
  static std::vector<unsigned char> crafted(const std::vector<unsigned char>& payload) {
    return test::file_of({kPaintingFileVersion, payload, std::nullopt});
  }
  std::string load_error(const std::filesystem::path& file) {
    try {
      Painting::load(file, 2);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }

  std::filesystem::path dir_;
};

TEST_F(BigPaintingFile, RoundTripIsExactOnAnyThreadCountWithItsHistory) {
  Painting p = big(90);
  ASSERT_EQ(p.canvas().allocated_tiles(), 90u);
  p.set_brush(test::round_brush(3.0));
  p.load_brush({{"red", 1.0}}, 30.0);
  test::stroke_line(p, 1.0, 1.0, 40.0, 9.0, 0.8f);
  test::stroke_line(p, 40.0, 1.0, 1.0, 19.0, 0.8f);
  ASSERT_GE(p.undo_depth(), 2u);
  const auto file = dir_ / "big.impasto", again = dir_ / "again.impasto";
  p.save(file);
  Painting one = Painting::load(file, 1), two = Painting::load(file, 2);
  for (const Painting* loaded : {&one, &two}) {
    EXPECT_EQ(loaded->state_hash(), p.state_hash()) << loaded->threads() << " threads";
    EXPECT_EQ(loaded->canvas().allocated_tiles(), p.canvas().allocated_tiles());
    EXPECT_EQ(loaded->undo_depth(), p.undo_depth());
    EXPECT_TRUE(loaded->load_warning().empty()) << loaded->load_warning();
  }
  two.save(again);
  EXPECT_EQ(read(again), read(file)) << "a loaded painting saves to the same bytes";
  ASSERT_TRUE(p.undo());
  ASSERT_TRUE(one.undo());
  ASSERT_TRUE(two.undo());
  EXPECT_EQ(one.state_hash(), p.state_hash());
  EXPECT_EQ(two.state_hash(), p.state_hash());
}

TEST_F(BigPaintingFile, OnePaintedTileOfAHugeCanvasCostsOneTile) {
  Painting p = big(1);
  const auto file = dir_ / "one.impasto";
  p.save(file);
  // The file holds the one tile (and its dry layer), not the canvas.
  EXPECT_LT(std::filesystem::file_size(file),
            painting_file_wet_tile_bytes(4) + painting_file_dry_tile_bytes(1) + 64 * 1024);
  const Painting loaded = Painting::load(file, 2);
  EXPECT_EQ(loaded.canvas().tile_count(), 313 * 313);
  EXPECT_EQ(loaded.canvas().allocated_tiles(), 1u);
  EXPECT_EQ(loaded.canvas().dry_layers().at(0).tiles.size(), 1u);
  // Its memory: the tile table (a pointer a tile) and the painted tile, not 400 M cells.
  const std::size_t table = static_cast<std::size_t>(loaded.canvas().tile_count()) * sizeof(void*);
  EXPECT_LT(loaded.memory_bytes(), table + 2 * painting_file_wet_tile_bytes(4) + 64 * 1024);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
}

TEST_F(BigPaintingFile, TheFirstBadTileInFileOrderIsNamedWhicheverBatchHoldsIt) {
  Painting p = big(90);
  p.set_saved_history_bytes(0);
  const auto file = dir_ / "crafted.impasto";
  p.save(file);
  const std::vector<unsigned char> good = test::sections_of(read(file)).payload;
  const auto put_float = [&](std::vector<unsigned char>& bytes, int tile, std::size_t value_at,
                             float value) {
    std::memcpy(bytes.data() + tile_offset(bytes, 90, tile) + 4 + value_at * 4, &value, 4);
  };
  const auto put_index = [&](std::vector<unsigned char>& bytes, int tile, std::uint32_t index) {
    std::memcpy(bytes.data() + tile_offset(bytes, 90, tile), &index, 4);
  };
  const auto index_of = [&](const std::vector<unsigned char>& bytes, int tile) {
    std::uint32_t index = 0;
    std::memcpy(&index, bytes.data() + tile_offset(bytes, 90, tile), 4);
    return index;
  };
  {  // A negative amount in the first batch and a repeated index in the second.
    std::vector<unsigned char> bytes = good;
    put_float(bytes, 50, 4096 + 7, -1.0f);  // wet_volume[7]
    put_index(bytes, 88, index_of(bytes, 87));
    write(file, crafted(bytes));
    const std::string error = load_error(file);
    EXPECT_NE(error.find("crafted.impasto: field 'tiles[50].wet_volume'"), std::string::npos)
        << error;
  }
  {  // The same repeated index alone.
    std::vector<unsigned char> bytes = good;
    put_index(bytes, 88, index_of(bytes, 87));
    write(file, crafted(bytes));
    const std::string error = load_error(file);
    EXPECT_NE(error.find("field 'tiles[88].index': tiles are not in ascending order"),
              std::string::npos)
        << error;
  }
  {  // An index beyond the canvas in the first batch, before a bad amount in the same batch.
    std::vector<unsigned char> bytes = good;
    put_index(bytes, 2, 4000000000u);
    put_float(bytes, 3, 0, std::numeric_limits<float>::quiet_NaN());
    write(file, crafted(bytes));
    const std::string error = load_error(file);
    EXPECT_NE(error.find("field 'tiles[2].index': 4000000000 exceeds the limit 97968"),
              std::string::npos)
        << error;
  }
  {  // Damage (no new checksum) is reported as damage, even where a field fails first.
    std::vector<unsigned char> bytes = good;
    put_index(bytes, 70, 4000000000u);
    std::vector<unsigned char> damaged = crafted(bytes);
    damaged.back() ^= 1;  // the payload's checksum (the file holds no history)
    write(file, damaged);
    const std::string error = load_error(file);
    EXPECT_NE(error.find("field 'checksum': does not match"), std::string::npos) << error;
  }
}

TEST_F(BigPaintingFile, TruncatedAnywhereFailsNamingTheFile) {
  Painting p = big(40);
  const auto file = dir_ / "cut.impasto";
  p.save(file);
  const std::vector<unsigned char> good = test::sections_of(read(file)).payload;
  for (std::size_t keep : {std::size_t{0}, std::size_t{7}, std::size_t{19}, std::size_t{100},
                           good.size() / 3, good.size() / 2, good.size() - 9, good.size() - 1}) {
    write(file, std::vector<unsigned char>(good.begin(), good.begin() + keep));
    const std::string error = load_error(file);
    EXPECT_NE(error.find("cut.impasto"), std::string::npos) << keep << ": " << error;
  }
}

}  // namespace
}  // namespace impasto::paintcore
