#include "impasto/render/render_painting.hpp"

#include <array>
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
                              const util::ProgressCallback& progress) {
  const paintcore::Canvas& canvas = painting.canvas();
  const int width = canvas.width_cells(), height = canvas.height_cells();
  // What a cell's shading reads around it, on either side (the shadows toward the light).
  const relief::Reach reach = relief::reach(relief::relief_params(settings, canvas.cell_mm()));
  const int margin = std::max(reach.top, reach.bottom);
  const SpectralPalette palette(settings, painting);
  // Each band's canvas rows, margins included, and the progress over all the bands' tiles.
  const auto band_span = [&](int y0) {
    return std::pair{std::max(0, y0 - margin), std::min(height, y0 + rows + margin)};
  };
  std::uint64_t total_tiles = 0;
  for (int y0 = 0; y0 < height; y0 += rows) {
    const auto [from, to] = band_span(y0);
    total_tiles +=
        static_cast<std::uint64_t>(canvas.tiles_x()) *
        static_cast<std::uint64_t>((to - from + paintcore::kTileSize - 1) / paintcore::kTileSize);
  }
  std::uint64_t tiles_before = 0;
  for (int y0 = 0; y0 < height; y0 += rows) {
    const int y1 = std::min(height, y0 + rows);
    const auto [from, to] = band_span(y0);
    paintcore::CutPaint cut;
    const paintcore::Canvas cropped =
        paintcore::reframed_canvas(canvas, paintcore::crop_frame(0, from, width, to - from),
                                   static_cast<int>(painting.pigment_slots().size()), cut);
    TileRenderer renderer(settings, palette);
    util::ProgressCallback band_progress;
    if (progress)
      band_progress = [&](std::uint64_t done, std::uint64_t) {
        progress(tiles_before + done, total_tiles);
      };
    renderer.render_all(cropped, band_progress);
    tiles_before += static_cast<std::uint64_t>(cropped.tile_count());
    Image whole = renderer.image();
    Image rows_image;
    rows_image.width = width;
    rows_image.height = y1 - y0;
    const auto first = whole.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(y0 - from) * width;
    rows_image.rgb.assign(first, first + 3 * static_cast<std::ptrdiff_t>(y1 - y0) * width);
    band(y0, rows_image);
  }
}

namespace {

// The memory of the file's pixels a render by bands keeps: PNG bytes (and their filtered copy
// as they are encoded), or OpenEXR's floats and halves.
std::uint64_t file_bytes_per_cell(const std::filesystem::path& path) {
  return image_file_type(path) == ImageFileType::png ? 3 + 3 : 12 + 8;
}

bool by_bands(const paintcore::Painting& painting, const RenderSettings& settings,
              int supersample) {
  return supersample == 1 &&
         painting.canvas().height_cells() > band_rows(painting.canvas().width_cells()) &&
         renders_by_bands(painting, settings);
}

}  // namespace

void check_render_to_file_memory(const paintcore::Painting& painting,
                                 const RenderSettings& settings, const std::filesystem::path& path,
                                 int supersample, const std::string& where) {
  const paintcore::Canvas& canvas = painting.canvas();
  if (!by_bands(painting, settings, supersample)) {
    if (supersample > 1) {
      const auto cells = static_cast<std::uint64_t>(canvas.tiles_x()) * canvas.tiles_y() *
                         paintcore::kTileCells * static_cast<std::uint64_t>(supersample) *
                         static_cast<std::uint64_t>(supersample);
      files::check_allocation(where,
                              "rendering the " + std::to_string(canvas.width_cells()) + " x " +
                                  std::to_string(canvas.height_cells()) + "-cell canvas " +
                                  std::to_string(supersample) + " x " +
                                  std::to_string(supersample) + " supersampled",
                              kRenderBytesPerCell * cells);
    } else {
      check_render_memory(canvas, where);
    }
    return;
  }
  const auto cells = static_cast<std::uint64_t>(canvas.width_cells()) *
                     static_cast<std::uint64_t>(canvas.height_cells());
  files::check_allocation(where,
                          "rendering the " + std::to_string(canvas.width_cells()) + " x " +
                              std::to_string(canvas.height_cells()) +
                              "-cell canvas (canvas.width_cells x canvas.height_cells) by bands "
                              "into " +
                              path.filename().string(),
                          2 * kBandRenderBytes + file_bytes_per_cell(path) * cells);
}

void render_painting_to_file(const paintcore::Painting& painting, const RenderSettings& settings,
                             const std::filesystem::path& path,
                             const util::ProgressCallback& progress, int supersample) {
  const bool png = image_file_type(path) == ImageFileType::png;
  RenderSettings file_settings = settings;
  if (!png) file_settings.display = DisplayEncoding::linear_srgb;
  if (by_bands(painting, file_settings, supersample)) {
    // A band at a time: the canvas's pixels are kept as the file stores them, not the render's
    // per-cell state (40 bytes a cell: a 16384 x 12288 canvas took 8 GB).
    const int width = painting.canvas().width_cells(), height = painting.canvas().height_cells();
    const int rows = band_rows(width);
    if (png) {
      std::vector<std::uint8_t> bytes(3 * static_cast<std::size_t>(width) *
                                      static_cast<std::size_t>(height));
      render_painting_by_bands(
          painting, file_settings, rows,
          [&](int first_row, const Image& band) {
            to_png_bytes(band.rgb.data(), band.rgb.size(),
                         bytes.data() + 3 * static_cast<std::size_t>(first_row) * width);
          },
          progress);
      std::string encoded;
      try {
        encoded = encode_png_bytes(bytes, width, height);
      } catch (const std::exception& error) {
        throw std::runtime_error(path.string() + ": cannot write PNG: " + error.what());
      }
      files::write_file_atomically(path, encoded);
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
          progress);
      write_exr(path, image);
    }
    return;
  }
  if (png) {
    write_png(path, render_painting_supersampled(painting, file_settings, supersample, progress));
  } else {
    write_exr(path, render_painting_supersampled(painting, file_settings, supersample, progress));
  }
}

}  // namespace impasto::render
