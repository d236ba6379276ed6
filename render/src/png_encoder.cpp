#include "impasto/render/png_encoder.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace impasto::render {
namespace {

constexpr int kChannels = 3;
constexpr int kStripRows = 64;          // rows deflated together: the unit of parallel work
constexpr std::size_t kWindow = 32768;  // deflate's window: the dictionary a strip starts from
// zlib level 1, not libpng's 6: on a 4096² render 1.7× as fast as level 3 for a file 5 %
// larger (`impasto bench render --json`: png_ms, png_bytes; docs/rendering.md).
constexpr int kLevel = 1;

// lround(clamp(v, 0, 1) · 255), NaN as 0, written without the library call so that it
// vectorises: t − trunc(t) is exact for 0 <= t < 256.
std::uint8_t to_byte(float value) {
  const float v = value >= 0.0f ? (value <= 1.0f ? value : 1.0f) : 0.0f;  // NaN: 0
  const float t = v * 255.0f;
  const int whole = static_cast<int>(t);
  return static_cast<std::uint8_t>(whole + (t - static_cast<float>(whole) >= 0.5f ? 1 : 0));
}

// One row filtered as libpng's default does: each of the five filters tried, the one whose
// bytes (as signed) sum smallest in magnitude kept. out: filter type byte, then the row;
// above: the row before (zeros for the first). Each filter is its own simple loop so that it
// vectorises.
void filter_row(const std::uint8_t* row, const std::uint8_t* above, std::size_t length,
                std::uint8_t* out, std::vector<std::uint8_t>& trial) {
  trial.resize(length);
  std::uint8_t* t = trial.data();
  const auto cost_of = [&] {
    std::uint32_t cost = 0;
    for (std::size_t i = 0; i < length; ++i) cost += t[i] < 128 ? t[i] : 256 - t[i];
    return cost;
  };
  std::uint32_t best_cost = UINT32_MAX;
  const auto keep = [&](int type) {
    const std::uint32_t cost = cost_of();
    if (cost < best_cost) {
      best_cost = cost;
      out[0] = static_cast<std::uint8_t>(type);
      std::copy_n(t, length, out + 1);
    }
  };
  const std::size_t n = std::min<std::size_t>(kChannels, length);
  std::copy_n(row, length, t);  // none
  keep(0);
  std::copy_n(row, n, t);  // sub
  for (std::size_t i = n; i < length; ++i) t[i] = static_cast<std::uint8_t>(row[i] - row[i - n]);
  keep(1);
  for (std::size_t i = 0; i < length; ++i) t[i] = static_cast<std::uint8_t>(row[i] - above[i]);
  keep(2);  // up
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>(row[i] - above[i] / 2);
  for (std::size_t i = n; i < length; ++i) {
    t[i] = static_cast<std::uint8_t>(row[i] - ((row[i - n] + above[i]) >> 1));
  }
  keep(3);  // average
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<std::uint8_t>(row[i] - above[i]);
  for (std::size_t i = n; i < length; ++i) {
    const int a = row[i - n], b = above[i], c = above[i - n];
    const int p = a + b - c;
    const int pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p, pc = p > c ? p - c : c - p;
    const int predictor = pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
    t[i] = static_cast<std::uint8_t>(row[i] - predictor);
  }
  keep(4);  // Paeth
}

// Raw deflate of [begin, end) of `data`, primed with up to 32 KiB before begin; the last
// strip finishes the stream, the others end on a byte boundary (a sync flush).
std::string deflate_strip(const std::uint8_t* data, std::size_t begin, std::size_t end, bool last) {
  z_stream z{};
  // The filtered strategy, as libpng uses for filtered rows.
  if (deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_FILTERED) != Z_OK) {
    throw std::runtime_error("PNG: zlib deflateInit2 failed");
  }
  const std::size_t primer = std::min(begin, kWindow);
  if (primer > 0 &&
      deflateSetDictionary(&z, data + begin - primer, static_cast<uInt>(primer)) != Z_OK) {
    deflateEnd(&z);
    throw std::runtime_error("PNG: zlib deflateSetDictionary failed");
  }
  std::string out(deflateBound(&z, static_cast<uLong>(end - begin)) + 16, '\0');
  z.next_in = const_cast<Bytef*>(data + begin);
  z.avail_in = static_cast<uInt>(end - begin);
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  const bool ok = last ? status == Z_STREAM_END : status == Z_OK && z.avail_in == 0;
  out.resize(out.size() - z.avail_out);
  deflateEnd(&z);
  if (!ok) throw std::runtime_error("PNG: zlib deflate failed");
  return out;
}

void put_u32(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(value >> shift));
}

void put_chunk(std::string& out, const char type[4], const std::string& body) {
  put_u32(out, static_cast<std::uint32_t>(body.size()));
  const std::size_t start = out.size();
  out.append(type, 4);
  out += body;
  const auto crc = crc32(0, reinterpret_cast<const Bytef*>(out.data() + start),
                         static_cast<uInt>(out.size() - start));
  put_u32(out, static_cast<std::uint32_t>(crc));
}

template <typename Work>
void parallel(std::size_t count, int threads, const Work& work) {
  const auto body = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) work(i);
                      });
  };
  if (threads > 0) {
    tbb::task_arena(threads).execute(body);
  } else {
    body();
  }
}

}  // namespace

void to_png_bytes(const float* rgb, std::size_t count, std::uint8_t* bytes) {
  std::transform(rgb, rgb + count, bytes, to_byte);
}

std::string encode_png(const Image& image, int threads) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(kChannels) *
                              static_cast<std::size_t>(image.width) *
                              static_cast<std::size_t>(image.height)) {
    throw std::runtime_error("PNG: the image has no pixels or a wrong buffer size");
  }
  const std::size_t row_bytes = kChannels * static_cast<std::size_t>(image.width);
  const auto height = static_cast<std::size_t>(image.height);
  const std::size_t strips = (height + kStripRows - 1) / kStripRows;
  std::vector<std::uint8_t> bytes(image.rgb.size());
  parallel(strips, threads, [&](std::size_t s) {
    const std::size_t y0 = s * kStripRows, y1 = std::min(height, y0 + kStripRows);
    to_png_bytes(image.rgb.data() + y0 * row_bytes, (y1 - y0) * row_bytes,
                 bytes.data() + y0 * row_bytes);
  });
  return encode_png_bytes(bytes, image.width, image.height, threads);
}

PngRowWriter::PngRowWriter(int width, int height, std::function<void(std::string_view)> out,
                           int threads)
    : width_(width), height_(height), threads_(threads), out_(std::move(out)) {
  if (width <= 0 || height <= 0) throw std::runtime_error("PNG: the image has no pixels");
  adler_ = adler32(0, nullptr, 0);
  std::string head("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put_u32(header, static_cast<std::uint32_t>(width));
  put_u32(header, static_cast<std::uint32_t>(height));
  header += std::string{'\x08', '\x02', '\0', '\0', '\0'};  // 8-bit RGB, deflate, no interlace
  put_chunk(head, "IHDR", header);
  put_chunk(head, "sRGB", std::string(1, '\0'));  // perceptual intent, as libpng writes it
  out_(head);
}

void PngRowWriter::add_rows(const std::uint8_t* rgb, int rows) {
  const auto row_bytes = static_cast<std::size_t>(kChannels) * static_cast<std::size_t>(width_);
  if (rows <= 0 || rows_done_ + rows > height_)
    throw std::runtime_error("PNG: more rows than the image's " + std::to_string(height_));
  if (rows_done_ % kStripRows != 0)
    throw std::runtime_error("PNG: rows must come in whole strips of 64 but for the last");
  const auto count = static_cast<std::size_t>(rows);
  const std::size_t strips = (count + kStripRows - 1) / kStripRows;
  // The rows filtered (a type byte each: PNG's uncompressed stream), after the last 32 KiB of
  // what came before, which primes the first strip's deflate.
  const std::size_t primer = history_.size();
  std::vector<std::uint8_t> filtered(primer + count * (row_bytes + 1));
  std::copy(history_.begin(), history_.end(), filtered.begin());
  if (above_.empty()) above_.assign(row_bytes, 0);
  parallel(strips, threads_, [&](std::size_t s) {
    std::vector<std::uint8_t> trial;
    const std::size_t y0 = s * kStripRows, y1 = std::min(count, y0 + kStripRows);
    for (std::size_t y = y0; y < y1; ++y) {
      filter_row(rgb + y * row_bytes, y > 0 ? rgb + (y - 1) * row_bytes : above_.data(), row_bytes,
                 &filtered[primer + y * (row_bytes + 1)], trial);
    }
  });
  const bool ends = rows_done_ + rows == height_;
  std::vector<std::string> deflated(strips);
  std::vector<uLong> adlers(strips);
  const auto strip_begin = [&](std::size_t s) { return primer + s * kStripRows * (row_bytes + 1); };
  const auto strip_end = [&](std::size_t s) {
    return std::min(filtered.size(), strip_begin(s) + kStripRows * (row_bytes + 1));
  };
  parallel(strips, threads_, [&](std::size_t s) {
    deflated[s] =
        deflate_strip(filtered.data(), strip_begin(s), strip_end(s), ends && s + 1 == strips);
    adlers[s] = adler32(adler32(0, nullptr, 0), filtered.data() + strip_begin(s),
                        static_cast<uInt>(strip_end(s) - strip_begin(s)));
  });
  // The zlib stream, a strip an IDAT: its header first, its Adler-32 last.
  for (std::size_t s = 0; s < strips; ++s) {
    adler_ =
        adler32_combine(adler_, adlers[s], static_cast<z_off_t>(strip_end(s) - strip_begin(s)));
    std::string body = rows_done_ == 0 && s == 0 ? "\x78\x01" : "";  // 32 KiB window, level 0
    body += deflated[s];
    if (ends && s + 1 == strips) put_u32(body, static_cast<std::uint32_t>(adler_));
    std::string chunk;
    put_chunk(chunk, "IDAT", body);
    out_(chunk);
  }
  above_.assign(rgb + (count - 1) * row_bytes, rgb + count * row_bytes);
  const std::size_t keep = std::min(kWindow, filtered.size());
  history_.assign(filtered.end() - static_cast<std::ptrdiff_t>(keep), filtered.end());
  rows_done_ += rows;
  if (ends) {
    std::string end;
    put_chunk(end, "IEND", {});
    out_(end);
  }
}

bool PngRowWriter::finished() const {
  return rows_done_ == height_;
}

std::string encode_png_bytes(const std::vector<std::uint8_t>& bytes, int width, int height,
                             int threads) {
  if (width <= 0 || height <= 0 ||
      bytes.size() != static_cast<std::size_t>(kChannels) * static_cast<std::size_t>(width) *
                          static_cast<std::size_t>(height)) {
    throw std::runtime_error("PNG: the image has no pixels or a wrong buffer size");
  }
  std::string png;
  PngRowWriter writer(
      width, height, [&](std::string_view part) { png += part; }, threads);
  writer.add_rows(bytes.data(), height);
  return png;
}

}  // namespace impasto::render
