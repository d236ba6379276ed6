#include "impasto/render/render_painting.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "impasto/files/atomic_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "impasto/paintcore/canvas_reframe.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/png_encoder.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/subsurface.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

void check_render_memory(const paintcore::Canvas& canvas, const std::string& where) {
  const auto cells =
      static_cast<std::uint64_t>(canvas.tiles_x()) * canvas.tiles_y() * paintcore::kTileCells;
  files::check_allocation(where,
                          "rendering the " + std::to_string(canvas.width_cells()) + " x " +
                              std::to_string(canvas.height_cells()) +
                              "-cell canvas (canvas.width_cells x canvas.height_cells)",
                          kRenderBytesPerCell * cells);
}

Image render_painting(const paintcore::Painting& painting, const RenderSettings& settings,
                      const util::ProgressCallback& progress) {
  if (settings.surface.model == SurfaceModel::ghs && settings.surface.subsurface) {
    return render_painting_with_subsurface(painting, settings);  // docs/surface.md
  }
  TileRenderer renderer(settings, SpectralPalette(settings, painting));
  renderer.render_all(painting.canvas(), progress);
  return renderer.image();
}

Image render_painting_supersampled(const paintcore::Painting& painting,
                                   const RenderSettings& settings, int supersample,
                                   const util::ProgressCallback& progress) {
  if (supersample < 1 || supersample > kMaxSupersample)
    throw std::runtime_error("supersample must be 1.." + std::to_string(kMaxSupersample) +
                             ", got " + std::to_string(supersample));
  if (supersample == 1) return render_painting(painting, settings, progress);
  if (!painting.canvas().cracks().empty())  // Painting::refined does not carry them
    throw std::runtime_error(
        "supersample: the painting has cracks, which the finer canvas does not carry; render "
        "it with supersample 1");
  const paintcore::Painting fine = painting.refined(supersample);
  check_render_memory(fine.canvas(), "supersampled render");
  RenderSettings linear = settings;
  linear.display = DisplayEncoding::linear_srgb;
  const Image samples = render_painting(fine, linear, progress);
  // Each pixel the mean of its block of samples, in linear sRGB, then to XYZ for the display.
  Image image;
  image.width = painting.canvas().width_cells();
  image.height = painting.canvas().height_cells();
  image.rgb.assign(3 * static_cast<std::size_t>(image.width) * image.height, 0.0f);
  const std::array<double, 9> to_xyz = invert_3x3(xyz_to_linear_srgb());
  const double share = 1.0 / (supersample * supersample);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::array<double, 3> sum{0.0, 0.0, 0.0};
      for (int j = 0; j < supersample; ++j)
        for (int i = 0; i < supersample; ++i) {
          const float* sample = samples.pixel(x * supersample + i, y * supersample + j);
          for (int c = 0; c < 3; ++c) sum[c] += sample[c];
        }
      float* out = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        out[c] = static_cast<float>(share * (to_xyz[3 * c] * sum[0] + to_xyz[3 * c + 1] * sum[1] +
                                             to_xyz[3 * c + 2] * sum[2]));
      }
    }
  }
  DisplayTransform(settings.display).apply(image.rgb.data(), image.rgb.size() / 3);
  return image;
}

bool renders_by_bands(const paintcore::Painting& painting, const RenderSettings& settings) {
  if (settings.light_type != LightType::directional && settings.light_type != LightType::diffuse)
    return false;
  if (settings.surface.model == SurfaceModel::ghs && settings.surface.subsurface) return false;
  if (!painting.canvas().cracks().empty()) return false;
  const SpectralPalette palette(settings, painting);
  for (int i = 0; i < palette.pigment_count(); ++i)
    if (!palette.flake_file(i).empty()) return false;
  return true;
}

int band_rows(int width_cells) {
  const std::uint64_t per_row = kRenderBytesPerCell * static_cast<std::uint64_t>(width_cells);
  const std::uint64_t tile_rows =
      std::max<std::uint64_t>(1, kBandRenderBytes / (per_row * paintcore::kTileSize));
  return static_cast<int>(std::min<std::uint64_t>(tile_rows, paintcore::kMaxCanvasCells)) *
         paintcore::kTileSize;
}

void render_painting_by_bands(const paintcore::Painting& painting, const RenderSettings& settings,
                              int rows,
                              const std::function<void(int first_row, const Image& band)>& band,
                              const util::ProgressCallback& progress, int scale) {
  if (scale < 1 || scale > 16)
    throw std::runtime_error("render by bands: field 'scale' must be in 1..16, got " +
                             std::to_string(scale));
  if (rows < 1)
    throw std::runtime_error("render by bands: field 'rows' must be at least 1, got " +
                             std::to_string(rows));
  const paintcore::Canvas& canvas = painting.canvas();
  // The canvas rendered: the painting's, or `scale` times finer (Painting::refined).
  const int width = canvas.width_cells() * scale, height = canvas.height_cells() * scale;
  // What a cell's shading reads around it, on either side (the shadows toward the light).
  const relief::Reach reach =
      relief::reach(relief::relief_params(settings, canvas.cell_mm() / scale));
  const int margin = std::max(reach.top, reach.bottom);
  // A finer cell interpolates the coarse cells around it (Catmull-Rom: one before, two after).
  constexpr int kRefineReach = 2;
  const SpectralPalette palette(settings, painting);
  // Each band's rows of the rendered canvas, its margins included: for a refined render, the
  // coarse rows they are refined from (whole, so the band starts at a coarse row's first).
  struct Span {
    int from, to;
  };
  const auto band_span = [&](int y0) {
    Span span{std::max(0, y0 - margin), std::min(height, y0 + rows + margin)};
    if (scale > 1) {
      span.from = std::max(0, span.from / scale - kRefineReach) * scale;
      span.to =
          std::min(canvas.height_cells(), (span.to + scale - 1) / scale + kRefineReach) * scale;
    }
    return span;
  };
  const auto tile_rows = [](int cells) {
    return static_cast<std::uint64_t>((cells + paintcore::kTileSize - 1) / paintcore::kTileSize);
  };
  std::uint64_t total_tiles = 0;
  for (int y0 = 0; y0 < height; y0 += rows) {
    const Span span = band_span(y0);
    total_tiles += tile_rows(width) * tile_rows(span.to - span.from);
  }
  std::uint64_t tiles_before = 0;
  for (int y0 = 0; y0 < height; y0 += rows) {
    const int y1 = std::min(height, y0 + rows);
    const Span span = band_span(y0);
    TileRenderer renderer(settings, palette);
    util::ProgressCallback band_progress;
    if (progress)
      band_progress = [&](std::uint64_t done, std::uint64_t) {
        progress(tiles_before + done, total_tiles);
      };
    if (scale == 1) {
      paintcore::CutPaint cut;
      const paintcore::Canvas cropped = paintcore::reframed_canvas(
          canvas, paintcore::crop_frame(0, span.from, width, span.to - span.from),
          painting.slot_count(), cut);
      renderer.render_all(cropped, band_progress);
    } else {
      const paintcore::Painting fine =
          painting
              .cropped(paintcore::crop_frame(0, span.from / scale, canvas.width_cells(),
                                             (span.to - span.from) / scale))
              .refined(scale);
      renderer.render_all(fine.canvas(), band_progress);
    }
    tiles_before += tile_rows(width) * tile_rows(span.to - span.from);
    const Image whole = renderer.image();
    Image rows_image;
    rows_image.width = width;
    rows_image.height = y1 - y0;
    const auto first = whole.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(y0 - span.from) * width;
    rows_image.rgb.assign(first, first + 3 * static_cast<std::ptrdiff_t>(y1 - y0) * width);
    band(y0, rows_image);
  }
}

namespace {

// The memory of the file's pixels a render by bands keeps: none for PNG (each band is encoded
// and written as it comes), OpenEXR's floats and halves.
std::uint64_t file_bytes_per_cell(const std::filesystem::path& path) {
  return image_file_type(path) == ImageFileType::png ? 0 : 12 + 8;
}

bool by_bands(const paintcore::Painting& painting, const RenderSettings& settings, int supersample,
              int scale) {
  const paintcore::Canvas& canvas = painting.canvas();
  // (A refined render goes by bands at any size: the finer canvas itself is what it saves.)
  return supersample == 1 &&
         (scale > 1 || canvas.height_cells() > band_rows(canvas.width_cells())) &&
         renders_by_bands(painting, settings);
}

std::string canvas_words(const paintcore::Canvas& canvas, int scale) {
  std::string words = "the " + std::to_string(canvas.width_cells()) + " x " +
                      std::to_string(canvas.height_cells()) +
                      "-cell canvas (canvas.width_cells x canvas.height_cells)";
  if (scale > 1) words += " " + std::to_string(scale) + " times finer";
  return words;
}

}  // namespace

void check_render_to_file_memory(const paintcore::Painting& painting,
                                 const RenderSettings& settings, const std::filesystem::path& path,
                                 int supersample, const std::string& where, int scale) {
  const paintcore::Canvas& canvas = painting.canvas();
  const auto cells = static_cast<std::uint64_t>(canvas.width_cells()) *
                     static_cast<std::uint64_t>(canvas.height_cells()) *
                     static_cast<std::uint64_t>(scale) * static_cast<std::uint64_t>(scale);
  if (by_bands(painting, settings, supersample, scale)) {
    // A band's render state and the image it becomes; refined, the band's finer painting too.
    const std::uint64_t band_bytes = (scale > 1 ? 4 : 2) * kBandRenderBytes;
    files::check_allocation(
        where,
        "rendering " + canvas_words(canvas, scale) + " by bands into " + path.filename().string(),
        band_bytes + file_bytes_per_cell(path) * cells);
    return;
  }
  // The whole canvas at once (the finer one, each of whose tiles the render shades), and its
  // supersamples.
  const auto samples =
      static_cast<std::uint64_t>(supersample) * static_cast<std::uint64_t>(supersample);
  const std::uint64_t tiles_cells = static_cast<std::uint64_t>(canvas.tiles_x()) *
                                    canvas.tiles_y() * paintcore::kTileCells * scale * scale;
  files::check_allocation(where,
                          "rendering " + canvas_words(canvas, scale) +
                              (supersample > 1 ? ", " + std::to_string(supersample) + " x " +
                                                     std::to_string(supersample) + " supersampled"
                                               : std::string()),
                          kRenderBytesPerCell * tiles_cells * samples);
}

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress, int supersample, int scale) {
  const bool png = image_file_type(path) == ImageFileType::png;
  RenderSettings file_settings = settings;
  if (!png) file_settings.display = DisplayEncoding::linear_srgb;
  if (!by_bands(painting, file_settings, supersample, scale)) {
    const std::optional<paintcore::Painting> fine =
        scale > 1 ? std::optional(painting.refined(scale)) : std::nullopt;
    const Image image =
        render_painting_supersampled(fine ? *fine : painting, file_settings, supersample, progress);
    if (png)
      write_png(path, image);
    else
      write_exr(path, image);
    return;
  }
  // A band at a time: the canvas's pixels are kept as the file stores them, not the render's
  // per-cell state (40 bytes a cell: a 16384 x 12288 canvas took 8 GB), nor a refined
  // painting's whole finer canvas.
  const int width = painting.canvas().width_cells() * scale;
  const int height = painting.canvas().height_cells() * scale;
  const int rows = band_rows(width);
  if (png) {
    // Each band encoded and written as it comes (the file appears whole or not at all).
    files::AtomicFile file(path);
    PngRowWriter writer(width, height, [&](std::string_view part) { file.write(part); });
    std::vector<std::uint8_t> bytes;
    render_painting_by_bands(
        painting, file_settings, rows,
        [&](int, const Image& band) {
          bytes.resize(band.rgb.size());
          to_png_bytes(band.rgb.data(), band.rgb.size(), bytes.data());
          try {
            writer.add_rows(bytes.data(), band.height);
          } catch (const std::runtime_error& error) {
            throw std::runtime_error(path.string() + ": cannot write PNG: " + error.what());
          }
        },
        progress, scale);
    file.commit();
  } else {
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    render_painting_by_bands(
        painting, file_settings, rows,
        [&](int first_row, const Image& band) {
          std::copy(band.rgb.begin(), band.rgb.end(),
                    image.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(first_row) * width);
        },
        progress, scale);
    write_exr(path, image);
  }
}

}  // namespace impasto::render
