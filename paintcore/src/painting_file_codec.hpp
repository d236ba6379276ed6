#pragma once
// Version 8's compressed sections (section_codec.hpp says how they are coded), written and
// read as a stream: a section is never held whole in memory.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hasher.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "section_codec.hpp"

namespace impasto::paintcore::file_io {

// Far above any painting's section (the file limit), so a crafted size is refused by name.
inline constexpr std::uint64_t kMaxSectionBytes = files::kMaxPaintingBytes;

// Takes a section's bytes as they are produced, writes the compressed frame to the file and
// hashes what it writes. Memory: a few blocks and zstd's window, whatever the section's size.
class CompressingSink {
 public:
  explicit CompressingSink(files::AtomicFile& out);
  ~CompressingSink();
  CompressingSink(const CompressingSink&) = delete;
  CompressingSink& operator=(const CompressingSink&) = delete;

  void write(const void* data, std::size_t size);
  // Ends the frame: everything is in the file after this.
  void finish();
  std::uint64_t section_bytes() const { return section_bytes_; }
  std::uint64_t stored_bytes() const { return stored_bytes_; }
  std::uint64_t digest() const { return hasher_.digest(); }

 private:
  void compress_block(bool last);
  files::AtomicFile& out_;
  void* context_;  // ZSTD_CCtx
  std::vector<unsigned char> block_, shuffled_, frame_;
  std::size_t filled_ = 0;
  std::uint64_t section_bytes_ = 0, stored_bytes_ = 0;
  StreamHasher hasher_;
};

// Reads a section back from `stored_bytes` of the file at its current position, hashing the
// stored bytes as they are read. A thread decodes up to a few MB ahead while the caller parses
// (it alone reads the file until the frame ends or skip_rest stops it). Damage (zstd's check
// fails, the frame ends early or runs on) throws std::runtime_error naming the file and the
// section.
class DecompressingSource {
 public:
  DecompressingSource(files::InputFile& in, std::uint64_t stored_bytes, std::string file,
                      std::string section);
  ~DecompressingSource();
  DecompressingSource(const DecompressingSource&) = delete;
  DecompressingSource& operator=(const DecompressingSource&) = delete;

  void read_exact(void* out, std::size_t size);
  // Reads (and hashes) the stored bytes not yet read, without decoding them: after a field
  // failed, the checksum says whether the file is damaged rather than crafted.
  void skip_rest();
  // After the last field: the frame must end here, with every stored byte used.
  void expect_end();
  // The checksum of the stored bytes: after skip_rest or expect_end.
  std::uint64_t digest() const { return hasher_.digest(); }

 private:
  struct Decoder;  // the decoding thread's side
  // The next decoded chunk; false when the decoder has ended (error_ says why, if it failed).
  bool next_chunk();
  void stop_decoder();
  [[noreturn]] void fail(const std::string& why) const;
  files::InputFile& in_;
  std::string file_, section_;
  std::unique_ptr<Decoder> decoder_;
  std::vector<unsigned char> chunk_;
  std::size_t chunk_pos_ = 0;
  StreamHasher hasher_;
};

}  // namespace impasto::paintcore::file_io
