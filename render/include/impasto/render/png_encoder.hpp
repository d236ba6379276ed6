#pragma once
// PNG encoding of a whole image in parallel: the rows are filtered and deflated in strips on
// TBB workers (each strip primed with the 32 KiB before it, as pigz does) and joined into
// one zlib stream, so a 4096² image costs a fraction of libpng's single-threaded write.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "impasto/render/image.hpp"

namespace impasto::render {

// The bytes of an 8-bit RGB PNG (with an sRGB chunk) of display-encoded values, clamped to
// [0, 1] and rounded, as write_png writes them. threads 0: TBB's default. The file's bytes do
// not depend on the thread count. Throws std::runtime_error for an empty image or a wrong
// buffer size, or when zlib fails.
std::string encode_png(const Image& image, int threads = 0);
// The same from bytes already converted (to_png_bytes), RGB row-major: a render by bands
// keeps 3 bytes a pixel instead of 12.
std::string encode_png_bytes(const std::vector<std::uint8_t>& rgb, int width, int height,
                             int threads = 0);
// Display-encoded values as the PNG stores them: lround(clamp(v, 0, 1) · 255), NaN as 0.
void to_png_bytes(const float* rgb, std::size_t count, std::uint8_t* bytes);

}  // namespace impasto::render
