#include "painting_file_codec.hpp"

#include <zstd.h>

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <new>
#include <stdexcept>
#include <thread>

namespace impasto::paintcore::file_io {

namespace {

// zstd's fastest level that loses nothing to level 1 on real paintings (the demo: 9.40 MB at
// -1 and at 1, 9.55 at -2, 10.0 at -4), and one worker: on two cores a save compresses while
// the painting is serialised (docs/painting-format.md has the figures).
constexpr int kLevel = -1;
constexpr int kWorkers = 1;
constexpr std::size_t kInputChunkBytes = 256 << 10;

ZSTD_CCtx* compressor(void* context) {
  return static_cast<ZSTD_CCtx*>(context);
}

void check(std::size_t result, const char* what) {
  if (ZSTD_isError(result))
    throw std::runtime_error(std::string("painting save: ") + what + ": " +
                             ZSTD_getErrorName(result));
}

}  // namespace

// Written a 32-bit value at a time so that the compiler vectorises both loops.
void shuffle_lanes(const unsigned char* in, std::size_t bytes, unsigned char* out) {
  const std::size_t values = bytes / 4;
  unsigned char* lane[4] = {out, out + values, out + 2 * values, out + 3 * values};
  for (std::size_t v = 0; v < values; ++v) {
    std::uint32_t word;
    std::memcpy(&word, in + 4 * v, 4);
    lane[0][v] = static_cast<unsigned char>(word);
    lane[1][v] = static_cast<unsigned char>(word >> 8);
    lane[2][v] = static_cast<unsigned char>(word >> 16);
    lane[3][v] = static_cast<unsigned char>(word >> 24);
  }
  if (bytes > 4 * values) std::memcpy(out + 4 * values, in + 4 * values, bytes - 4 * values);
}

void unshuffle_lanes(const unsigned char* in, std::size_t bytes, unsigned char* out) {
  const std::size_t values = bytes / 4;
  const unsigned char* lane[4] = {in, in + values, in + 2 * values, in + 3 * values};
  for (std::size_t v = 0; v < values; ++v) {
    const std::uint32_t word =
        static_cast<std::uint32_t>(lane[0][v]) | static_cast<std::uint32_t>(lane[1][v]) << 8 |
        static_cast<std::uint32_t>(lane[2][v]) << 16 | static_cast<std::uint32_t>(lane[3][v]) << 24;
    std::memcpy(out + 4 * v, &word, 4);
  }
  if (bytes > 4 * values) std::memcpy(out + 4 * values, in + 4 * values, bytes - 4 * values);
}

// --- writing

CompressingSink::CompressingSink(files::AtomicFile& out)
    : out_(out),
      context_(ZSTD_createCCtx()),
      block_(kCodecBlockBytes),
      shuffled_(kCodecBlockBytes),
      frame_(ZSTD_CStreamOutSize()) {
  if (context_ == nullptr) throw std::bad_alloc();
  check(ZSTD_CCtx_setParameter(compressor(context_), ZSTD_c_compressionLevel, kLevel),
        "compression level");
  // A library built without threads refuses workers; it then compresses on this thread.
  (void)ZSTD_CCtx_setParameter(compressor(context_), ZSTD_c_nbWorkers, kWorkers);
}

CompressingSink::~CompressingSink() {
  ZSTD_freeCCtx(compressor(context_));
}

void CompressingSink::write(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  section_bytes_ += size;
  while (size > 0) {
    const std::size_t take = std::min(size, kCodecBlockBytes - filled_);
    std::memcpy(block_.data() + filled_, p, take);
    filled_ += take;
    p += take;
    size -= take;
    if (filled_ == kCodecBlockBytes) compress_block(false);
  }
}

void CompressingSink::finish() {
  compress_block(true);
}

void CompressingSink::compress_block(bool last) {
  shuffle_lanes(block_.data(), filled_, shuffled_.data());
  ZSTD_inBuffer input{shuffled_.data(), filled_, 0};
  filled_ = 0;
  const ZSTD_EndDirective mode = last ? ZSTD_e_end : ZSTD_e_continue;
  for (;;) {
    ZSTD_outBuffer output{frame_.data(), frame_.size(), 0};
    const std::size_t left = ZSTD_compressStream2(compressor(context_), &output, &input, mode);
    check(left, "compressing");
    out_.write(frame_.data(), output.pos);
    hasher_.bytes(frame_.data(), output.pos);
    stored_bytes_ += output.pos;
    if (last ? left == 0 : input.pos == input.size) break;
  }
}

// --- reading

struct DecompressingSource::Decoder {
  static constexpr std::size_t kChunkBytes = 1 << 20;
  static constexpr std::size_t kChunksAhead = 3;

  Decoder(files::InputFile& in, std::uint64_t stored_bytes, StreamHasher& hasher, std::string where)
      : in(in),
        stored_left(stored_bytes),
        hasher(hasher),
        where(std::move(where)),
        context(ZSTD_createDCtx()),
        input(kInputChunkBytes),
        shuffled(kCodecBlockBytes) {
    if (context == nullptr) throw std::bad_alloc();
  }
  ~Decoder() { ZSTD_freeDCtx(context); }

  void run() {
    try {
      while (!frame_ended) {
        {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return stop || ready.size() < kChunksAhead; });
          if (stop) break;
        }
        std::vector<unsigned char> chunk(kChunkBytes);
        std::size_t filled = 0;
        while (filled < kChunkBytes && !frame_ended) filled += decode_block(chunk.data() + filled);
        chunk.resize(filled);
        {
          std::lock_guard lock(mutex);
          if (!chunk.empty()) ready.push_back(std::move(chunk));
        }
        changed.notify_all();
      }
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex);
      error = e.what();
    }
    {
      std::lock_guard lock(mutex);
      finished = true;
    }
    changed.notify_all();
  }

  // Decodes one codec block (the last may be shorter) into `out`; returns its size.
  std::size_t decode_block(unsigned char* out) {
    ZSTD_outBuffer output{shuffled.data(), shuffled.size(), 0};
    while (output.pos < output.size) {
      if (!fill_input()) throw std::runtime_error(where + " is truncated (its data ends early)");
      ZSTD_inBuffer in_buffer{input.data(), input_size, input_pos};
      const std::size_t result = ZSTD_decompressStream(context, &output, &in_buffer);
      input_pos = in_buffer.pos;
      if (ZSTD_isError(result))
        throw std::runtime_error(where + " is damaged (zstd: " + ZSTD_getErrorName(result) + ")");
      if (result == 0) {
        frame_ended = true;
        break;
      }
    }
    unshuffle_lanes(shuffled.data(), output.pos, out);
    return output.pos;
  }

  bool fill_input() {
    if (input_pos < input_size) return true;
    if (stored_left == 0) return false;
    input_size = static_cast<std::size_t>(std::min<std::uint64_t>(stored_left, input.size()));
    in.read_exact(input.data(), input_size);
    hasher.bytes(input.data(), input_size);
    stored_left -= input_size;
    input_pos = 0;
    return true;
  }

  files::InputFile& in;
  std::uint64_t stored_left;
  StreamHasher& hasher;
  const std::string where;  // "FILE: the SECTION"
  ZSTD_DCtx* context;
  std::vector<unsigned char> input, shuffled;
  std::size_t input_pos = 0, input_size = 0;
  bool frame_ended = false;

  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::vector<unsigned char>> ready;
  bool stop = false, finished = false;
  std::string error;
  std::thread thread;
};

DecompressingSource::DecompressingSource(files::InputFile& in, std::uint64_t stored_bytes,
                                         std::string file, std::string section)
    : in_(in), file_(std::move(file)), section_(std::move(section)) {
  decoder_ = std::make_unique<Decoder>(in, stored_bytes, hasher_, file_ + ": the " + section_);
  decoder_->thread = std::thread([decoder = decoder_.get()] { decoder->run(); });
}

DecompressingSource::~DecompressingSource() {
  stop_decoder();
}

void DecompressingSource::fail(const std::string& why) const {
  throw std::runtime_error(file_ + ": the " + section_ + " " + why);
}

void DecompressingSource::stop_decoder() {
  {
    std::lock_guard lock(decoder_->mutex);
    decoder_->stop = true;
  }
  decoder_->changed.notify_all();
  if (decoder_->thread.joinable()) decoder_->thread.join();
}

bool DecompressingSource::next_chunk() {
  {
    std::unique_lock lock(decoder_->mutex);
    decoder_->changed.wait(lock, [&] { return !decoder_->ready.empty() || decoder_->finished; });
    if (decoder_->ready.empty()) {
      if (!decoder_->error.empty()) throw std::runtime_error(decoder_->error);
      return false;
    }
    chunk_ = std::move(decoder_->ready.front());
    decoder_->ready.pop_front();
  }
  decoder_->changed.notify_all();
  chunk_pos_ = 0;
  return true;
}

void DecompressingSource::read_exact(void* out, std::size_t size) {
  auto* p = static_cast<unsigned char*>(out);
  while (size > 0) {
    if (chunk_pos_ == chunk_.size() && !next_chunk())
      fail("is truncated (its data ends before its last field)");
    const std::size_t take = std::min(size, chunk_.size() - chunk_pos_);
    std::memcpy(p, chunk_.data() + chunk_pos_, take);
    chunk_pos_ += take;
    p += take;
    size -= take;
  }
}

void DecompressingSource::skip_rest() {
  stop_decoder();
  Decoder& d = *decoder_;
  d.input_pos = d.input_size;
  while (d.fill_input()) d.input_pos = d.input_size;
}

void DecompressingSource::expect_end() {
  if (chunk_pos_ != chunk_.size() || next_chunk())
    fail("holds more data than its fields (a crafted or damaged file)");
  stop_decoder();
  const Decoder& d = *decoder_;
  if (d.input_pos != d.input_size || d.stored_left != 0)
    fail("has bytes after its compressed data (a crafted or damaged file)");
}

// --- whole sections

std::vector<unsigned char> compress_section(std::span<const unsigned char> section) {
  std::vector<unsigned char> shuffled(section.size());
  for (std::size_t at = 0; at < section.size(); at += kCodecBlockBytes)
    shuffle_lanes(section.data() + at, std::min(kCodecBlockBytes, section.size() - at),
                  shuffled.data() + at);
  std::vector<unsigned char> stored(ZSTD_compressBound(section.size()));
  const std::size_t size =
      ZSTD_compress(stored.data(), stored.size(), shuffled.data(), shuffled.size(), kLevel);
  check(size, "compressing");
  stored.resize(size);
  return stored;
}

std::vector<unsigned char> decompress_section(std::span<const unsigned char> stored,
                                              std::uint64_t section_bytes) {
  std::vector<unsigned char> shuffled(static_cast<std::size_t>(section_bytes));
  const std::size_t size =
      ZSTD_decompress(shuffled.data(), shuffled.size(), stored.data(), stored.size());
  if (ZSTD_isError(size) || size != shuffled.size())
    throw std::runtime_error("painting section: not a compressed section of that size");
  std::vector<unsigned char> section(shuffled.size());
  for (std::size_t at = 0; at < section.size(); at += kCodecBlockBytes)
    unshuffle_lanes(shuffled.data() + at, std::min(kCodecBlockBytes, section.size() - at),
                    section.data() + at);
  return section;
}

}  // namespace impasto::paintcore::file_io
