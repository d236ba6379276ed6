// Version 8's compressed sections (section_codec.hpp, painting_file_codec.hpp): the lane shuffle
// is undone exactly, a section streamed through the sink and the source comes back byte for
// byte across block and chunk boundaries, damage names the file and the section, and older
// uncompressed files still load.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "../common/scratch_folder.hpp"
#include "hostile_paintings.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "older_painting_files.hpp"
#include "painting_file_codec.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using file_io::CompressingSink;
using file_io::DecompressingSource;

class SectionCodec : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = impasto::test::scratch_folder(
        std::string("impasto_codec_") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Floats of paint-like heights with noise in every mantissa bit, and a few odd bytes.
  static std::vector<unsigned char> sample_section(std::size_t bytes) {
    std::vector<unsigned char> out(bytes);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> height(0.0f, 0.8f);
    for (std::size_t at = 0; at + 4 <= bytes; at += 4) {
      const float value = (at / 4) % 3 == 0 ? 0.0f : height(random);
      std::memcpy(out.data() + at, &value, 4);
    }
    for (std::size_t at = bytes & ~std::size_t{3}; at < bytes; ++at) out[at] = 0xab;
    return out;
  }

  // Writes `section` through the streaming sink in pieces of `piece` bytes; returns the
  // stored size (the file holds only the frame).
  std::uint64_t write_streamed(const std::filesystem::path& file,
                               const std::vector<unsigned char>& section, std::size_t piece) {
    files::AtomicFile out(file);
    CompressingSink sink(out);
    for (std::size_t at = 0; at < section.size(); at += piece)
      sink.write(section.data() + at, std::min(piece, section.size() - at));
    sink.finish();
    EXPECT_EQ(sink.section_bytes(), section.size());
    out.commit();
    return sink.stored_bytes();
  }

  std::filesystem::path dir_;
};

TEST_F(SectionCodec, TheLaneShuffleIsUndoneExactlyForAnySize) {
  for (std::size_t bytes : {0u, 1u, 3u, 4u, 7u, 4096u, 65535u, 65536u}) {
    const auto in = sample_section(bytes);
    std::vector<unsigned char> shuffled(bytes), back(bytes);
    file_io::shuffle_lanes(in.data(), bytes, shuffled.data());
    file_io::unshuffle_lanes(shuffled.data(), bytes, back.data());
    EXPECT_EQ(back, in) << bytes << " bytes";
    if (bytes >= 8) {  // the first lane holds every value's first byte
      EXPECT_EQ(shuffled[0], in[0]);
      EXPECT_EQ(shuffled[1], in[4]);
      EXPECT_EQ(shuffled[bytes / 4], in[1]);
    }
  }
}

TEST_F(SectionCodec, AStreamedSectionComesBackByteForByte) {
  // Across codec blocks (64 KiB) and the reader's chunks (1 MiB), written in odd pieces and
  // read in odd pieces.
  const auto section = sample_section(3 * (1 << 20) + 12345);
  const auto file = dir_ / "section.bin";
  const std::uint64_t stored = write_streamed(file, section, 1000);
  EXPECT_LT(stored, section.size());
  files::InputFile in(file, "section", 1ull << 30);
  ASSERT_EQ(in.size(), stored);
  DecompressingSource source(in, stored, file.string(), "payload");
  std::vector<unsigned char> back(section.size());
  for (std::size_t at = 0, piece = 1; at < back.size(); at += piece, piece = piece * 3 % 70001 + 1)
    source.read_exact(back.data() + at, std::min(piece, back.size() - at));
  EXPECT_NO_THROW(source.expect_end());
  EXPECT_EQ(back, section);
  // The whole-section helpers agree with the stream.
  EXPECT_EQ(file_io::decompress_section(file_io::compress_section(section), section.size()),
            section);
}

TEST_F(SectionCodec, DamageAndTruncationNameTheFileAndSection) {
  const auto section = sample_section(300000);
  const auto file = dir_ / "damaged.bin";
  const std::uint64_t stored = write_streamed(file, section, 4096);
  const auto read_all = [&](std::uint64_t stored_bytes) -> std::string {
    files::InputFile in(file, "section", 1ull << 30);
    DecompressingSource source(in, stored_bytes, file.string(), "undo history");
    std::vector<unsigned char> back(section.size());
    try {
      source.read_exact(back.data(), back.size());
      source.expect_end();
    } catch (const std::runtime_error& e) {
      source.skip_rest();
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(read_all(stored), "no error");
  // Cut short: the frame ends early.
  EXPECT_NE(read_all(stored / 2).find(file.string() + ": the undo history is truncated"),
            std::string::npos);
  // Bytes after the frame are refused, not ignored.
  {
    std::vector<unsigned char> bytes = test::file_bytes(file);
    bytes.push_back(0);
    test::write_bytes(file, bytes);
    EXPECT_NE(read_all(stored + 1).find("has bytes after its compressed data"), std::string::npos);
  }
  // A damaged frame header: zstd's own checks say so. (Damage inside a block may decode to
  // other bytes: the section's checksum, which the painting file checks, finds that.)
  {
    std::vector<unsigned char> bytes = test::file_bytes(file);
    bytes.pop_back();
    bytes[0] ^= 0x5a;
    test::write_bytes(file, bytes);
    const std::string error = read_all(stored);
    EXPECT_NE(error, "no error");
    EXPECT_NE(error.find(file.string() + ": the undo history"), std::string::npos) << error;
  }
}

TEST_F(SectionCodec, PaintingsShrinkAndVersionSevenFilesStillLoad) {
  Painting p(CanvasSpec{256, 128, 254.0, 3}, 1);
  p.set_brush(test::round_brush(4.0));
  p.load_brush({{"red", 1.0}, {"white", 1.0}}, 40.0);
  for (int k = 0; k < 6; ++k) test::stroke_line(p, 2.0, 2.0 + k, 20.0, 10.0 - k, 0.8f);
  const auto file = dir_ / "now.impasto";
  p.save(file);
  const auto bytes = test::file_bytes(file);
  const test::FileSections sections = test::sections_of(bytes);
  ASSERT_TRUE(sections.history.has_value());
  // Six strokes over the same tiles: the history's tiles cost only the cells each changed
  // (each step's tiles coded against their newer states).
  std::uint64_t payload_stored = 0, history_stored = 0;
  std::memcpy(&payload_stored, bytes.data() + kPaintingFileMagicBytes + 4, 8);
  std::memcpy(&history_stored, bytes.data() + kPaintingFileMagicBytes + 4 + 24 + payload_stored, 8);
  EXPECT_LT(payload_stored, sections.payload.size() / 3);
  EXPECT_LT(history_stored, sections.history->size() / 10)
      << history_stored << " bytes stored for " << sections.history->size();
  // The same payload as version 7 stored it (uncompressed, without the parameters added
  // since) loads to the same painting.
  const auto old = dir_ / "seven.impasto";
  test::write_painting_file(old, 7, test::without_params_after(sections.payload, 7));
  const Painting seven = Painting::load(old, 1);
  EXPECT_EQ(seven.state_hash(), p.state_hash());
  EXPECT_EQ(seven.load_warning(), "");
}

}  // namespace
}  // namespace impasto::paintcore
