// JPEG pictures read through libjpeg-turbo's TurboJPEG interface, and the choice between a PNG
// and a JPEG by the file's first bytes.
#include <turbojpeg.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "impasto/render/image.hpp"

namespace impasto::render {
namespace {

struct TurboJpegDeleter {
  void operator()(void* handle) const { tjDestroy(handle); }
};
using TurboJpeg = std::unique_ptr<void, TurboJpegDeleter>;

std::string jpeg_error(const TurboJpeg& handle) {
  return tjGetErrorStr2(handle.get());
}

}  // namespace

Image read_jpeg(const std::filesystem::path& path) {
  const std::string file = files::read_whole_file(path, "JPEG image", files::kMaxImageFileBytes);
  const TurboJpeg handle(tjInitDecompress());
  if (!handle) throw std::runtime_error(path.string() + ": cannot read JPEG: " + tjGetErrorStr());
  const auto* bytes = reinterpret_cast<const unsigned char*>(file.data());
  const auto size = static_cast<unsigned long>(file.size());
  int width = 0, height = 0, subsampling = 0, colourspace = 0;
  if (tjDecompressHeader3(handle.get(), bytes, size, &width, &height, &subsampling, &colourspace) !=
      0)
    throw std::runtime_error(path.string() + ": cannot read JPEG: " + jpeg_error(handle));
  if (colourspace == TJCS_CMYK || colourspace == TJCS_YCCK)
    throw std::runtime_error(path.string() +
                             ": a CMYK JPEG (a print file); save it as RGB to open it here");
  if (width <= 0 || height <= 0)
    throw std::runtime_error(path.string() + ": cannot read JPEG: no frame header with a size");
  // Checked before decoding: the 8-bit and float copies in the memory budget. (A JPEG's
  // compression has no useful bound, so there is no ratio check as for PNG.)
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  files::check_allocation(path.string(),
                          "the header's size (SOF width x height " + std::to_string(width) + " x " +
                              std::to_string(height) + ")",
                          15 * pixels);
  std::vector<unsigned char> rgb(3 * pixels);
  // A progressive file's scans are limited (a crafted one can ask for millions); a damaged
  // file that still decodes, with a warning, is taken as real pictures often are.
  if (tjDecompress2(handle.get(), bytes, size, rgb.data(), width, 0, height, TJPF_RGB,
                    TJFLAG_LIMITSCANS) != 0 &&
      tjGetErrorCode(handle.get()) == TJERR_FATAL)
    throw std::runtime_error(path.string() + ": cannot read JPEG: " + jpeg_error(handle));
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(rgb.size());
  std::transform(rgb.begin(), rgb.end(), image.rgb.begin(),
                 [](unsigned char b) { return static_cast<float>(b) / 255.0f; });
  return image;
}

Image read_picture(const std::filesystem::path& path) {
  std::string head(8, '\0');
  {
    files::InputFile in(path, "picture", files::kMaxImageFileBytes);
    in.stream().read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.stream().gcount()));
  }
  static const std::string kPngSignature("\x89PNG\r\n\x1a\n", 8);
  if (head == kPngSignature) return read_png(path);
  if (head.size() >= 3 && static_cast<unsigned char>(head[0]) == 0xFF &&
      static_cast<unsigned char>(head[1]) == 0xD8 && static_cast<unsigned char>(head[2]) == 0xFF)
    return read_jpeg(path);
  throw std::runtime_error(path.string() + ": not a PNG or JPEG picture (its first bytes are " +
                           "neither's signature)");
}

}  // namespace impasto::render
