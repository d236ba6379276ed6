// Crack maps as grey PNG images (grey = depth), through libpng's simplified API.
#include <png.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/cracks/craquelure.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"

namespace impasto::cracks {

CrackMap read_crack_png(const std::filesystem::path& path, const CrackImageSettings& s) {
  const std::string name = path.string();
  if (!(s.max_depth_mm > 0.0) || !std::isfinite(s.max_depth_mm) || !(s.depth_to_half_width > 0.0) ||
      !std::isfinite(s.depth_to_half_width)) {
    throw std::runtime_error(name + ": max_depth_mm and depth_to_half_width must be > 0");
  }
  const std::string file = files::read_whole_file(path, "PNG crack map", files::kMaxImageFileBytes);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) {
    throw std::runtime_error(name + ": cannot read PNG: " + image.message);
  }
  // Frees libpng's state however this function is left.
  std::unique_ptr<png_image, void (*)(png_image*)> guard(&image, png_image_free);
  if (image.width < 1 || image.height < 1 || image.width > CrackMap::kMaxSide ||
      image.height > CrackMap::kMaxSide) {
    throw std::runtime_error(name + ": image size " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " is outside [1, " +
                             std::to_string(CrackMap::kMaxSide) + "]");
  }
  // Grey levels are taken as they are stored: 16-bit files are read as 16-bit, 8-bit files
  // as 8-bit, so that no gamma conversion changes the depths.
  const bool sixteen_bit = (image.format & PNG_FORMAT_FLAG_LINEAR) != 0;
  image.format = sixteen_bit ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
  const double full_scale = sixteen_bit ? 65535.0 : 255.0;
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  // Checked before decoding: the pixels (at least a bit each) must fit in the file, and what
  // reading takes (16-bit grey, 8-bit grey) in the memory budget.
  const std::string declared = "the header's size (IHDR width x height " +
                               std::to_string(image.width) + " x " + std::to_string(image.height) +
                               ")";
  files::check_decoded_size(name, declared, count / 8, file.size());
  files::check_allocation(name, declared, 3 * static_cast<std::uint64_t>(count));
  std::vector<png_uint_16> grey(count);
  std::vector<png_byte> grey8(sixteen_bit ? 0 : count);
  void* buffer = sixteen_bit ? static_cast<void*>(grey.data()) : static_cast<void*>(grey8.data());
  if (!png_image_finish_read(&image, nullptr, buffer, 0, nullptr)) {
    throw std::runtime_error(name + ": cannot decode PNG: " + image.message);
  }
  if (!sixteen_bit) std::copy(grey8.begin(), grey8.end(), grey.begin());
  CrackMap map(static_cast<int>(image.width), static_cast<int>(image.height), s.cell_mm);
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const png_uint_16 g = grey[static_cast<std::size_t>(y) * image.width + x];
      if (g == 0) continue;
      const double depth = s.max_depth_mm * g / full_scale;
      map.set(x, y,
              {static_cast<float>(depth), static_cast<float>(depth / s.depth_to_half_width),
               s.shape, s.exposed_layer});
    }
  }
  return map;
}

void write_crack_png(const CrackMap& map, const std::filesystem::path& path, double max_depth_mm) {
  const std::string name = path.string();
  if (!(max_depth_mm > 0.0) || !std::isfinite(max_depth_mm)) {
    throw std::runtime_error(name + ": max_depth_mm must be finite and > 0");
  }
  std::vector<png_uint_16> grey(static_cast<std::size_t>(map.width()) * map.height(), 0);
  map.for_each_crack([&](int x, int y, const CrackCell& c) {
    const double v = std::min(1.0, c.depth_mm / max_depth_mm);
    grey[static_cast<std::size_t>(y) * map.width() + x] =
        static_cast<png_uint_16>(std::max(1.0, std::lround(v * 65535.0) * 1.0));
  });
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(map.width());
  image.height = static_cast<png_uint_32>(map.height());
  image.format = PNG_FORMAT_LINEAR_Y;
  // Encoded in memory, then saved atomically (files::AtomicFile).
  png_alloc_size_t size = 0;
  std::string encoded;
  if (png_image_write_to_memory(&image, nullptr, &size, 0, grey.data(), 0, nullptr)) {
    encoded.resize(size);
    if (!png_image_write_to_memory(&image, encoded.data(), &size, 0, grey.data(), 0, nullptr))
      size = 0;
  }
  if (size == 0) {
    const std::string why = image.message;
    png_image_free(&image);
    throw std::runtime_error(name + ": cannot write PNG: " + why);
  }
  encoded.resize(size);
  files::write_file_atomically(path, encoded);
}

}  // namespace impasto::cracks
