#pragma once
// PNG encoding of a whole image in parallel: the rows are filtered and deflated in strips on
// TBB workers (each strip primed with the 32 KiB before it, as pigz does) and joined into
// one zlib stream, so a 4096² image costs a fraction of libpng's single-threaded write.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/render/image.hpp"

namespace impasto::render {

// The bytes of an 8-bit RGB PNG (with an sRGB chunk) of display-encoded values, clamped to
// [0, 1] and rounded, as write_png writes them. threads 0: TBB's default. The file's bytes do
// not depend on the thread count. Throws std::runtime_error for an empty image or a wrong
// buffer size, or when zlib fails.
std::string encode_png(const Image& image, int threads = 0);
// The same from bytes already converted (to_png_bytes), RGB row-major.
std::string encode_png_bytes(const std::vector<std::uint8_t>& rgb, int width, int height,
                             int threads = 0);
// The same file written a band of rows at a time, for images too large to hold whole: each
// band's rows are filtered and deflated in strips of 64 rows in parallel (each strip primed
// with the 32 KiB of the stream before it, which the writer keeps across bands) and handed to
// `out` as IDAT chunks at once. Bands come in order, whole strips but for the last; the bytes
// are encode_png's whatever the bands. Throws std::runtime_error on rows beyond the image.
class PngRowWriter {
 public:
  PngRowWriter(int width, int height, std::function<void(std::string_view)> out, int threads = 0);
  void add_rows(const std::uint8_t* rgb, int rows);
  bool finished() const;  // every row was added (and the file ended)

 private:
  int width_, height_, threads_;
  std::function<void(std::string_view)> out_;
  int rows_done_ = 0;
  unsigned long adler_ = 0;            // of the stream so far
  std::vector<std::uint8_t> above_;    // the last row added (the next row's filter reads it)
  std::vector<std::uint8_t> history_;  // the stream's last 32 KiB (the next strip's primer)
};
// Display-encoded values as the PNG stores them: lround(clamp(v, 0, 1) · 255), NaN as 0.
void to_png_bytes(const float* rgb, std::size_t count, std::uint8_t* bytes);

}  // namespace impasto::render
