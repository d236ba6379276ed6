#pragma once
// A rendered image and its files.
#include <filesystem>
#include <vector>

namespace impasto::render {

// Packed RGB floats, row-major, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // 3 · width · height

  float* pixel(int x, int y) {
    return rgb.data() + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x));
  }
  const float* pixel(int x, int y) const { return const_cast<Image*>(this)->pixel(x, y); }
};

// The image files a render can write, chosen by the file's extension.
enum class ImageFileType { png, exr };
// From the extension, case-insensitive; throws std::runtime_error naming the file otherwise.
ImageFileType image_file_type(const std::filesystem::path& path);

// 8-bit RGB PNG of display-encoded values (clamped to [0, 1], rounded). Throws
// std::runtime_error naming the file when it cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);
// Half-float RGB OpenEXR of linear values, full range kept. Throws std::runtime_error.
void write_exr(const std::filesystem::path& path, const Image& image);
// PNG images back as floats in [0, 1] (8- or 16-bit RGB/RGBA/grey); for tests and tools.
Image read_png(const std::filesystem::path& path);
// JPEG images (baseline or progressive; grey, YCbCr or RGB) as floats in [0, 1]. The declared
// size is checked against the memory budget before decoding; CMYK is refused by name.
Image read_jpeg(const std::filesystem::path& path);
// A PNG or a JPEG, told apart by the file's first bytes (not its name): for pictures a user
// opens (the window's reference image). Throws std::runtime_error naming the file otherwise.
Image read_picture(const std::filesystem::path& path);

}  // namespace impasto::render
