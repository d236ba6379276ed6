#include "impasto/render/relief_maps.hpp"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/util/text.hpp"

namespace impasto::render {
namespace {

constexpr const char* kOffsetKey = "impasto:height_offset_mm";
constexpr const char* kStepKey = "impasto:height_step_mm";
constexpr const char* kCellKey = "impasto:cell_mm";
constexpr const char* kConventionKey = "impasto:normal_convention";

using TextChunks = std::vector<std::pair<std::string, std::string>>;

std::string exact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string lower_extension(const std::filesystem::path& path) {
  return util::ascii_lowercase(path.extension().string());
}

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}
void no_flush(png_structp) {}

// A PNG of `rows` (already in PNG's byte order) with tEXt chunks and no colour chunk; false
// when libpng fails. No object is made after setjmp: a longjmp skips no destructor.
bool encode_png_rows(int width, int height, int bit_depth, int color_type,
                     std::vector<png_bytep>& rows, std::vector<png_text>& text, std::string& out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &out, append_bytes, no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
               bit_depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_text(png, info, text.data(), static_cast<int>(text.size()));
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

void write_png_rows(const std::filesystem::path& path, int width, int height, int bit_depth,
                    int color_type, std::vector<std::uint8_t>& bytes, const TextChunks& chunks) {
  const std::size_t row_bytes = bytes.size() / static_cast<std::size_t>(height);
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) rows[static_cast<std::size_t>(y)] = bytes.data() + y * row_bytes;
  std::vector<png_text> text(chunks.size());
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    text[k].compression = PNG_TEXT_COMPRESSION_NONE;
    text[k].key = const_cast<char*>(chunks[k].first.c_str());
    text[k].text = const_cast<char*>(chunks[k].second.c_str());
    text[k].text_length = chunks[k].second.size();
  }
  std::string encoded;
  if (!encode_png_rows(width, height, bit_depth, color_type, rows, text, encoded))
    throw std::runtime_error(path.string() + ": cannot write PNG (libpng failed)");
  files::write_file_atomically(path, encoded);
}

void check_grid(const HeightGrid& h, const std::filesystem::path& path) {
  if (h.width <= 0 || h.height <= 0 ||
      h.mm.size() != static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height) ||
      !(h.cell_mm > 0.0))
    throw std::runtime_error(path.string() + ": the height grid is empty or of a wrong size");
  for (float v : h.mm)
    if (!std::isfinite(v)) throw std::runtime_error(path.string() + ": a height is not finite");
}

// What read_height_png gathers from libpng; filled before any longjmp could skip it.
struct PngRead {
  const std::string* file = nullptr;
  std::size_t offset = 0;
};

void read_bytes(png_structp png, png_bytep out, png_size_t size) {
  auto* in = static_cast<PngRead*>(png_get_io_ptr(png));
  if (size > in->file->size() - in->offset) png_error(png, "the file is truncated");
  std::memcpy(out, in->file->data() + in->offset, size);
  in->offset += size;
}

// libpng's part of reading a height map. The function that calls setjmp holds no C++
// object of its own: everything it changes is in *d, and what builds strings or grows vectors
// is a function of its own (not inlined), so a longjmp clobbers nothing.
struct PngDecode {
  PngRead source;
  png_uint_32 width = 0, height = 0;
  std::vector<std::uint8_t> bytes;  // big-endian samples, row-major
  std::vector<png_bytep> rows;
  TextChunks chunks;
  std::string problem;
};

// Whether the header describes a height map that fits; says why not in d->problem.
[[gnu::noinline]] bool accept_header(PngDecode* d, int bit_depth, int color_type) {
  if (bit_depth != 16 || color_type != PNG_COLOR_TYPE_GRAY) {
    d->problem = "not a 16-bit greyscale PNG";
    return false;
  }
  const std::uint64_t pixels = static_cast<std::uint64_t>(d->width) * d->height;
  // Deflate packs at most 1032:1; the samples and the floats must fit the memory budget.
  if (pixels == 0 || pixels > d->source.file->size() * 1032ull ||
      6 * pixels > files::memory_budget_bytes()) {
    d->problem = "its declared size (IHDR " + std::to_string(d->width) + " x " +
                 std::to_string(d->height) + ") does not fit the file or the memory budget";
    return false;
  }
  d->bytes.resize(2 * pixels);
  d->rows.resize(d->height);
  for (png_uint_32 y = 0; y < d->height; ++y) d->rows[y] = d->bytes.data() + 2ull * d->width * y;
  return true;
}

[[gnu::noinline]] void collect_text(png_structp png, png_infop info, PngDecode* d) {
  png_textp text = nullptr;
  int count = 0;
  png_get_text(png, info, &text, &count);
  for (int k = 0; k < count; ++k) d->chunks.emplace_back(text[k].key, text[k].text);
}

bool decode_grey16(PngDecode* d) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &d->source, read_bytes);
  png_read_info(png, info);
  d->width = png_get_image_width(png, info);
  d->height = png_get_image_height(png, info);
  if (!accept_header(d, png_get_bit_depth(png, info), png_get_color_type(png, info)))
    png_error(png, "refused");
  png_read_image(png, d->rows.data());
  png_read_end(png, info);
  collect_text(png, info, d);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

HeightGrid read_height_png(const std::filesystem::path& path) {
  const std::string file = files::read_whole_file(path, "height map", files::kMaxImageFileBytes);
  PngDecode d;
  d.source = PngRead{&file, 0};
  if (!decode_grey16(&d))
    throw std::runtime_error(path.string() + ": cannot read the height map PNG" +
                             (d.problem.empty() ? std::string() : ": " + d.problem));
  const std::vector<std::uint8_t>& bytes = d.bytes;
  const TextChunks& chunks = d.chunks;
  const std::uint64_t pixels = static_cast<std::uint64_t>(d.width) * d.height;
  HeightGrid grid;
  const auto number = [&](const char* key) {
    for (const auto& [k, v] : chunks)
      if (k == key) {
        char* end = nullptr;
        const double value = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0' || !std::isfinite(value)) break;
        return value;
      }
    throw std::runtime_error(path.string() + ": tEXt chunk '" + key + "' is missing or no number");
  };
  const double offset = number(kOffsetKey), step = number(kStepKey);
  grid.cell_mm = number(kCellKey);
  grid.width = static_cast<int>(d.width);
  grid.height = static_cast<int>(d.height);
  grid.mm.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i)
    grid.mm[i] = static_cast<float>(offset + step * ((bytes[2 * i] << 8) | bytes[2 * i + 1]));
  return grid;
}

void write_height_exr(const std::filesystem::path& path, const HeightGrid& h) {
  try {
    Imf::Header header(h.width, h.height);
    header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    header.insert(kCellKey, Imf::DoubleAttribute(h.cell_mm));
    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);
      Imf::FrameBuffer frame;
      frame.insert("Z",
                   Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(h.mm.data())),
                              sizeof(float), sizeof(float) * static_cast<std::size_t>(h.width)));
      file.setFrameBuffer(frame);
      file.writePixels(h.height);
    }
    files::write_file_atomically(path, stream.str());
  } catch (const Iex::BaseExc& e) {
    throw std::runtime_error(path.string() + ": cannot write OpenEXR: " + e.what());
  }
}

HeightGrid read_height_exr(const std::filesystem::path& path) {
  const std::string bytes = files::read_whole_file(path, "height map", files::kMaxImageFileBytes);
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    HeightGrid h;
    h.width = window.max.x - window.min.x + 1;
    h.height = window.max.y - window.min.y + 1;
    const auto* cell = file.header().findTypedAttribute<Imf::DoubleAttribute>(kCellKey);
    if (!cell || !file.header().channels().findChannel("Z"))
      throw std::runtime_error(path.string() + ": not a height map (no channel Z or no " +
                               kCellKey + ")");
    h.cell_mm = cell->value();
    files::check_allocation(path.string(), "the height map's pixels",
                            4ull * static_cast<std::uint64_t>(h.width) * h.height);
    h.mm.resize(static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height));
    Imf::FrameBuffer frame;
    char* origin = reinterpret_cast<char*>(h.mm.data()) -
                   (static_cast<std::ptrdiff_t>(window.min.x) +
                    static_cast<std::ptrdiff_t>(window.min.y) * h.width) *
                       static_cast<std::ptrdiff_t>(sizeof(float));
    frame.insert("Z", Imf::Slice(Imf::FLOAT, origin, sizeof(float),
                                 sizeof(float) * static_cast<std::size_t>(h.width)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return h;
  } catch (const Iex::BaseExc& e) {
    throw std::runtime_error(path.string() + ": cannot read OpenEXR: " + e.what());
  }
}

}  // namespace

HeightGrid surface_heights(const paintcore::Canvas& canvas) {
  HeightGrid h;
  h.width = canvas.width_cells();
  h.height = canvas.height_cells();
  h.cell_mm = canvas.cell_mm();
  files::check_allocation("height map", "the canvas's heights",
                          4ull * static_cast<std::uint64_t>(h.width) * h.height);
  h.mm.resize(static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height));
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x)
      h.mm[static_cast<std::size_t>(y) * h.width + x] = paintcore::surface_height_mm(canvas, x, y);
  return h;
}

void write_height_map(const std::filesystem::path& path, const HeightGrid& heights) {
  const std::string extension = lower_extension(path);
  if (extension != ".png" && extension != ".exr")
    throw std::runtime_error(path.string() + ": unknown height map type '" + extension +
                             "' (expected .png or .exr)");
  check_grid(heights, path);
  if (extension == ".exr") return write_height_exr(path, heights);
  const auto [lo, hi] = std::minmax_element(heights.mm.begin(), heights.mm.end());
  const double offset = *lo;
  const double step = (static_cast<double>(*hi) - *lo) / 65535.0;
  std::vector<std::uint8_t> bytes(2 * heights.mm.size());
  for (std::size_t i = 0; i < heights.mm.size(); ++i) {
    const auto v = static_cast<std::uint16_t>(
        step > 0.0 ? std::clamp(std::lround((heights.mm[i] - offset) / step), 0L, 65535L) : 0L);
    bytes[2 * i] = static_cast<std::uint8_t>(v >> 8);  // PNG is big-endian
    bytes[2 * i + 1] = static_cast<std::uint8_t>(v & 0xff);
  }
  write_png_rows(
      path, heights.width, heights.height, 16, PNG_COLOR_TYPE_GRAY, bytes,
      {{kOffsetKey, exact(offset)}, {kStepKey, exact(step)}, {kCellKey, exact(heights.cell_mm)}});
}

HeightGrid read_height_map(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".exr") return read_height_exr(path);
  if (extension == ".png") return read_height_png(path);
  throw std::runtime_error(path.string() + ": unknown height map type '" + extension +
                           "' (expected .png or .exr)");
}

Image normal_map(const HeightGrid& h) {
  Image image;
  image.width = h.width;
  image.height = h.height;
  image.rgb.resize(3 * h.mm.size());
  const auto slope = [&](int a, int b, int x0, int y0, int x1, int y1) {
    return (static_cast<double>(h.at(x1, y1)) - h.at(x0, y0)) / ((b - a) * h.cell_mm);
  };
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      const int xl = std::max(x - 1, 0), xr = std::min(x + 1, h.width - 1);
      const int yu = std::max(y - 1, 0), yd = std::min(y + 1, h.height - 1);
      const double dx = xr > xl ? slope(xl, xr, xl, y, xr, y) : 0.0;
      const double dy_down = yd > yu ? slope(yu, yd, x, yu, x, yd) : 0.0;
      // z = h(x, y) with y down the rows; the normal (-dh/dx, -dh/dY, 1) with Y = -y up.
      const double nx = -dx, ny = dy_down, length = std::sqrt(nx * nx + ny * ny + 1.0);
      float* px = image.pixel(x, y);
      px[0] = static_cast<float>(0.5 * (nx / length + 1.0));
      px[1] = static_cast<float>(0.5 * (ny / length + 1.0));
      px[2] = static_cast<float>(0.5 * (1.0 / length + 1.0));
    }
  return image;
}

void write_normal_map(const std::filesystem::path& path, const HeightGrid& heights) {
  if (lower_extension(path) != ".png")
    throw std::runtime_error(path.string() + ": a normal map is written as .png");
  check_grid(heights, path);
  const Image image = normal_map(heights);
  std::vector<std::uint8_t> bytes(image.rgb.size());
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] =
        static_cast<std::uint8_t>(std::lround(std::clamp(image.rgb[i], 0.0f, 1.0f) * 255.0f));
  write_png_rows(path, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, bytes,
                 {{kConventionKey, "OpenGL +Y up (tangent space: R +X right, G +Y up, B +Z out)"},
                  {kCellKey, exact(heights.cell_mm)}});
}

}  // namespace impasto::render
