// The painting's crack layer: Painting::set_cracks, and the cracks section of the .impasto
// file (since version 2): round trip, older files, bad records named by file and field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "older_painting_files.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

// The version these tests write: save() writes 7, which adds the long steps' settings after
// the other parameters, and before it 6, which adds at the end of the payload the surface
// section (paint_surface.hpp), here empty: a u32 zero and the brush's medium (2 f32);
// payload_of() takes both away.
constexpr std::uint32_t kVersion = 5;
constexpr std::size_t kNoSurfacesBytes = 4 + 2 * 4;
// Version 5's payload: the canvas spec (24 bytes, then the weave's origin, 2 i64, since
// version 5), the f64 parameters (7 in older versions), after the cracks section the brush's
// body and bristles (u8 + 4 f64) (since version 3), then the pigments' records (since version
// 4; without a record source: a u32 zero).
constexpr std::size_t kWeaveOriginOffset = 4 + 4 + 8 + 8;
constexpr std::size_t kWeaveOriginBytes = 2 * 8;
static_assert(test::kParamsOffset == kWeaveOriginOffset + kWeaveOriginBytes);
constexpr std::size_t kBrushExtrasBytes = 1 + 4 * 8;
constexpr std::size_t kNoRecordsBytes = 4;
// Bytes of a cracks section holding one tile with one crack cell.
constexpr std::size_t kOneCrackSection = 4 + (4 + 4) + (2 + 4 + 4 + 1 + 1);

class CrackFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("impasto_cracks_file_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // 130 x 70 cells (3 x 2 tiles), one dry layer under a wet stroke.
  static Painting sample() {
    Painting p(CanvasSpec{130, 70, 254.0, 4}, 1);
    p.set_brush(BrushSettings{"filbert", 2.0, 0.6});
    p.load_brush({{"red", 1.0}, {"blue", 1.0}}, 5.0);
    test::stroke_line(p, 2.0, 3.0, 12.0, 5.0, 0.8f, 20, 10.0f, 0.0f, 45.0f);
    p.dry(0.5);
    return p;
  }

  static CrackLayer some_cracks() {
    CrackLayer cracks;
    CrackTile& a = cracks.ensure_tile(0);
    a.cells[5 * 64 + 7] = {0.12f, 0.03f, 1, kCrackExposesGround};
    a.cells[5 * 64 + 8] = {0.05f, 0.02f, 0, 0};
    CrackTile& b = cracks.ensure_tile(5);  // the bottom-right edge tile: x < 2, y < 6 inside
    b.cells[3 * 64 + 1] = {0.3f, 0.1f, 4, kCrackExposesGround};
    return cracks;
  }

  std::string load_error(const std::filesystem::path& file) {
    try {
      Painting::load(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }
  // A version-4 payload from a version-5 one: without the weave's origin (an uncropped canvas's
  // is zero).
  static std::vector<unsigned char> as_version_four(std::vector<unsigned char> payload) {
    payload.erase(payload.begin() + kWeaveOriginOffset,
                  payload.begin() + kWeaveOriginOffset + kWeaveOriginBytes);
    return payload;
  }
  // A version-2 payload from a version-5 one of a painting with a brush and no pigment records:
  // IMPaSTo's seven parameters (any valid values, the adhesion film kept) and no brush extras
  // or records at the end.
  static std::vector<unsigned char> as_version_two(std::vector<unsigned char> payload) {
    const auto fields = simulation_param_fields(kVersion);
    const auto film = std::find_if(fields.begin(), fields.end(), [](const NamedParam& f) {
      return std::string(f.name) == "min_film_mm";
    });
    double min_film = 0.0;
    std::memcpy(&min_film, payload.data() + test::kParamsOffset + 8 * (film - fields.begin()), 8);
    std::vector<unsigned char> old(7 * 8);
    const double values[7] = {0.1, 1.0 / 30, 0.001, 0.2, 0.3, 0.5, min_film};
    std::memcpy(old.data(), values, sizeof values);
    payload = as_version_four(std::move(payload));
    constexpr std::size_t params = kWeaveOriginOffset;  // where they are without the origin
    payload.erase(payload.begin() + params,
                  payload.begin() + params + static_cast<std::ptrdiff_t>(8 * fields.size()));
    payload.insert(payload.begin() + params, old.begin(), old.end());
    payload.resize(payload.size() - kBrushExtrasBytes - kNoRecordsBytes);
    return payload;
  }
  static std::vector<unsigned char> read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // Writes a file from header fields and a payload, with the payload's checksum.
  static void write(const std::filesystem::path& file, std::uint32_t version,
                    const std::vector<unsigned char>& payload) {
    test::write_painting_file(file, version, payload);
  }
  // The payload alone (a version-5 file may carry the undo history after it), as version 5
  // wrote it: without a version-7 file's long steps and a version-6 file's empty surface
  // section.
  static std::vector<unsigned char> payload_of(const std::vector<unsigned char>& file_bytes) {
    std::vector<unsigned char> payload = test::as_version_six(test::payload_of(file_bytes));
    EXPECT_GE(payload.size(), kNoSurfacesBytes);
    payload.resize(payload.size() - kNoSurfacesBytes);
    return payload;
  }

  std::filesystem::path dir_;
};

TEST_F(CrackFileTest, AnUncrackedPaintingHoldsNoCrackMemory) {
  const Painting p = sample();
  EXPECT_TRUE(p.cracks().empty());
  EXPECT_EQ(p.cracks().memory_bytes(), 0u);
  EXPECT_EQ(p.cracks().tile(0), nullptr);
}

TEST_F(CrackFileTest, SetCracksMarksOnlyTheChangedTilesDirtyAndDropsEmptyTiles) {
  Painting p = sample();
  const Painting::ChangeSubscriber changes = p.subscribe_changes();
  (void)p.take_changes(changes);
  const std::uint64_t before = p.state_hash();
  CrackLayer cracks = some_cracks();
  cracks.ensure_tile(3);  // allocated but without a crack: dropped
  p.set_cracks(std::move(cracks));
  EXPECT_EQ(tile_indices(p.take_changes(changes)), (std::vector<int>{0, 5}));
  EXPECT_EQ(p.cracks().allocated_tiles(), 2u);
  EXPECT_EQ(p.cracks().crack_cells(), 3u);
  EXPECT_NE(p.state_hash(), before);
  // Setting the same cracks again changes nothing.
  p.set_cracks(some_cracks());
  EXPECT_TRUE(p.take_changes(changes).empty());
  // Removing them restores the uncracked state and hash.
  p.set_cracks(CrackLayer{});
  EXPECT_EQ(tile_indices(p.take_changes(changes)), (std::vector<int>{0, 5}));
  EXPECT_EQ(p.state_hash(), before);
  EXPECT_EQ(p.cracks().memory_bytes(), 0u);
}

TEST_F(CrackFileTest, SetCracksRejectsBadRecordsNamingTheField) {
  Painting p = sample();
  const auto error_of = [&](CrackRecord record, int tile = 0, int cell = 0) -> std::string {
    CrackLayer cracks;
    cracks.ensure_tile(tile).cells[static_cast<std::size_t>(cell)] = record;
    try {
      p.set_cracks(std::move(cracks));
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(error_of({nan, 0.1f, 0, 0xFF}).find("depth_mm"), std::string::npos);
  EXPECT_NE(error_of({0.1f, -1.0f, 0, 0xFF}).find("half_width_mm"), std::string::npos);
  EXPECT_NE(error_of({0.1f, 0.0f, 0, 0xFF}).find("half_width_mm"), std::string::npos);
  EXPECT_NE(error_of({0.1f, 0.1f, 6, 0xFF}).find("shape"), std::string::npos);
  EXPECT_NE(error_of({0.1f, 0.1f, 0, 1}).find("exposed_layer"), std::string::npos);
  EXPECT_NE(error_of({0.1f, 0.1f, 0, 0xFF}, 5, 3 * 64 + 2).find("outside the canvas"),
            std::string::npos);
  EXPECT_NE(error_of({0.1f, 0.1f, 0, 0xFF}, 6).find("tile 6"), std::string::npos);
  EXPECT_TRUE(p.cracks().empty());  // nothing changed by a rejected layer
  EXPECT_EQ(error_of({0.1f, 0.1f, 0, 0}, 0, 0), "no error");
}

TEST_F(CrackFileTest, SaveThenLoadKeepsTheCracks) {
  Painting p = sample();
  p.set_cracks(some_cracks());
  const auto file = dir_ / "cracked.impasto";
  p.save(file);
  Painting loaded = Painting::load(file, 1);
  EXPECT_TRUE(loaded.cracks() == p.cracks());
  EXPECT_EQ(loaded.cracks().crack_cells(), 3u);
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  // A renderer of the loaded painting shades the cracked tiles.
  const std::vector<int> dirty = tile_indices(loaded.take_changes(loaded.subscribe_changes()));
  EXPECT_NE(std::find(dirty.begin(), dirty.end(), 5), dirty.end());
}

TEST_F(CrackFileTest, VersionOneFilesStillLoad) {
  // A version-1 file is a version-2 file without the cracks section (an empty one is a
  // u32 zero at the end of the payload).
  const Painting p = sample();
  const auto file = dir_ / "v3.impasto";
  p.save(file);
  std::vector<unsigned char> payload = as_version_two(payload_of(read(file)));
  ASSERT_GE(payload.size(), 4u);
  EXPECT_EQ(payload[payload.size() - 4] | payload[payload.size() - 1], 0);
  payload.resize(payload.size() - 4);
  const auto v1 = dir_ / "v1.impasto";
  write(v1, 1, payload);
  const Painting loaded = Painting::load(v1, 1);
  EXPECT_TRUE(loaded.cracks().empty());
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  // A version-1 file that carries a cracks section has bytes after its last field.
  payload.insert(payload.end(), {0, 0, 0, 0});
  write(v1, 1, payload);
  EXPECT_NE(load_error(v1).find("unexpected bytes"), std::string::npos) << load_error(v1);
}

TEST_F(CrackFileTest, PigmentRecordsRoundTripAndVersionThreeFilesLoadWithoutThem) {
  Painting p = sample();
  p.set_pigment_record("red", "# quantity: kubelka_munk\n# name: red\n");
  p.set_pigment_record("blue", std::string(100000, 'b'));  // longer than a name may be
  const auto file = dir_ / "records.impasto";
  p.save(file);
  Painting loaded = Painting::load(file, 1);
  EXPECT_EQ(loaded.pigment_records(), p.pigment_records());
  EXPECT_EQ(loaded.state_hash(), p.state_hash());
  // Version 3: the same payload without the records section.
  const Painting bare = sample();
  bare.save(file);
  std::vector<unsigned char> payload = as_version_four(payload_of(read(file)));
  payload.resize(payload.size() - kNoRecordsBytes);
  write(file, 3, payload);
  const Painting old = Painting::load(file, 1);
  EXPECT_TRUE(old.pigment_records().empty());
  EXPECT_EQ(old.state_hash(), bare.state_hash());
}

TEST_F(CrackFileTest, NewSlotsTakeTheirRecordsFromTheRecordSource) {
  Painting::set_pigment_record_source([](const std::string& name) {
    return std::map<std::string, std::string>{{name, "record of " + name}, {"white", "w"}};
  });
  Painting p(CanvasSpec{64, 64, 254.0, 4}, 1);
  p.slot_for("green");
  Painting::set_pigment_record_source({});
  EXPECT_EQ(p.pigment_records(),
            (std::map<std::string, std::string>{{"green", "record of green"}, {"white", "w"}}));
}

TEST_F(CrackFileTest, CracksOnALayerThatAnUndoRemovedStillSaveAndLoad) {
  Painting p = sample();
  CrackLayer cracks;
  cracks.ensure_tile(0).cells[100] = {0.01f, 0.01f, 1, 0};  // walls of dry layer 0
  p.set_cracks(std::move(cracks));
  ASSERT_TRUE(p.undo());  // the drying: no dry layer left
  EXPECT_TRUE(p.canvas().dry_layers().empty());
  const auto file = dir_ / "undone.impasto";
  p.save(file);
  EXPECT_TRUE(Painting::load(file, 1).cracks() == p.cracks());
}

TEST_F(CrackFileTest, BadCrackRecordsInAFileNameTheFileAndField) {
  Painting p(CanvasSpec{100, 80, 254.0, 4}, 1);
  CrackLayer cracks;
  cracks.ensure_tile(1).cells[2 * 64 + 3] = {0.2f, 0.05f, 2, kCrackExposesGround};
  p.set_cracks(std::move(cracks));
  const auto good = dir_ / "good.impasto";
  p.save(good);
  const std::vector<unsigned char> payload = payload_of(read(good));
  const std::size_t section = payload.size() - kOneCrackSection - kNoRecordsBytes;
  const auto bad = dir_ / "bad.impasto";
  const auto corrupt = [&](std::size_t offset, const void* value, std::size_t bytes) {
    std::vector<unsigned char> edited = payload;
    std::memcpy(edited.data() + section + offset, value, bytes);
    write(bad, kVersion, edited);
    return load_error(bad);
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(), huge = 1e30f, zero = 0.0f;
  const std::uint8_t shape = 17, layer = 0;
  const std::uint32_t tile = 9, count = 0;
  const std::uint16_t cell = 4096;
  std::string e = corrupt(4 + 4 + 4 + 2, &nan, 4);
  EXPECT_NE(e.find("bad.impasto"), std::string::npos) << e;
  EXPECT_NE(e.find("cracks.tiles[0].cells[0].depth_mm"), std::string::npos) << e;
  e = corrupt(4 + 4 + 4 + 2, &zero, 4);
  EXPECT_NE(e.find("depth_mm"), std::string::npos) << e;
  e = corrupt(4 + 4 + 4 + 2 + 4, &huge, 4);
  EXPECT_NE(e.find("half_width_mm"), std::string::npos) << e;
  e = corrupt(4 + 4 + 4 + 2 + 8, &shape, 1);
  EXPECT_NE(e.find("'shape'"), std::string::npos) << e;
  e = corrupt(4 + 4 + 4 + 2 + 9, &layer, 1);  // dry layer 0 of a painting without one: an
  EXPECT_EQ(e, "no error");                   // undo of a drying leaves such cracks behind
  e = corrupt(4, &tile, 4);
  EXPECT_NE(e.find("cracks.tiles[0].index"), std::string::npos) << e;
  e = corrupt(8, &count, 4);
  EXPECT_NE(e.find("cracks.tiles[0].count"), std::string::npos) << e;
  e = corrupt(12, &cell, 2);
  EXPECT_NE(e.find("cracks.tiles[0].cells[0].cell"), std::string::npos) << e;
  // The unedited bytes, re-written, load.
  write(bad, kVersion, payload);
  EXPECT_EQ(load_error(bad), "no error");
}

}  // namespace
}  // namespace impasto::paintcore
