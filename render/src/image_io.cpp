#include <png.h>

#include <ImfRgbaFile.h>
#include <ImfStdIO.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>

#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/png_encoder.hpp"
#include "impasto/util/text.hpp"

namespace impasto::render {
namespace {

void check_size(const Image& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() !=
          3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    throw std::runtime_error(path.string() + ": image has no pixels or a wrong buffer size");
  }
}

}  // namespace

// Encoded in memory in parallel (png_encoder.hpp), then saved atomically (files::AtomicFile).
void write_png(const std::filesystem::path& path, const Image& image) {
  check_size(image, path);
  std::string encoded;
  try {
    encoded = encode_png(image);
  } catch (const std::exception& error) {
    throw std::runtime_error(path.string() + ": cannot write PNG: " + error.what());
  }
  files::write_file_atomically(path, encoded);
}

Image read_png(const std::filesystem::path& path) {
  const std::string file = files::read_whole_file(path, "PNG image", files::kMaxImageFileBytes);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, file.data(), file.size())) {
    const std::string message = png.message;
    png_image_free(&png);
    throw std::runtime_error(path.string() + ": cannot read PNG: " + message);
  }
  // Checked before decoding: the pixels (at least a bit each) must fit in the file, and the
  // 8-bit and float copies in the memory budget.
  const auto pixels = static_cast<std::uint64_t>(png.width) * png.height;
  const std::string declared = "the header's size (IHDR width x height " +
                               std::to_string(png.width) + " x " + std::to_string(png.height) + ")";
  try {
    files::check_decoded_size(path.string(), declared, pixels / 8, file.size());
    files::check_allocation(path.string(), declared, 15 * pixels);
  } catch (const std::exception&) {
    png_image_free(&png);
    throw;
  }
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw std::runtime_error(path.string() + ": cannot read PNG: " + message);
  }
  Image image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(bytes.size());
  std::transform(bytes.begin(), bytes.end(), image.rgb.begin(),
                 [](std::uint8_t b) { return static_cast<float>(b) / 255.0f; });
  return image;
}

void write_exr(const std::filesystem::path& path, const Image& image) {
  check_size(image, path);
  std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(image.width) *
                                static_cast<std::size_t>(image.height));
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    pixels[i] = Imf::Rgba(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2], 1.0f);
  }
  // Encoded in memory, then saved atomically (files::AtomicFile).
  try {
    Imf::StdOSStream stream;
    {
      // Blocks of scan lines compressed on every core (the file's bytes are the same).
      Imf::RgbaOutputFile file(stream, Imf::Header(image.width, image.height), Imf::WRITE_RGB,
                               static_cast<int>(std::thread::hardware_concurrency()));
      file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(image.width));
      file.writePixels(image.height);
    }
    files::write_file_atomically(path, stream.str());
  } catch (const Iex::BaseExc& e) {
    throw std::runtime_error(path.string() + ": cannot write OpenEXR: " + e.what());
  }
}

ImageFileType image_file_type(const std::filesystem::path& path) {
  const std::string extension = util::ascii_lowercase(path.extension().string());
  if (extension == ".png") return ImageFileType::png;
  if (extension == ".exr") return ImageFileType::exr;
  throw std::runtime_error(path.string() + ": unknown image type '" + extension +
                           "' (expected .png or .exr)");
}

}  // namespace impasto::render
