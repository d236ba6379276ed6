// impasto bench zoom: how far the window's zoomed-out view is from the painting as it should
// look at that zoom — the CPU render supersampled 4 x 4 (relief finer than a cell shaded, not
// aliased) box-filtered over each screen pixel's footprint — and what a frame costs. Beside
// it, the CPU's one-sample-a-cell render box-filtered the same way: what filtering cells alone
// gives. Errors in 8-bit sRGB levels (the largest of a pixel's three channels).
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/box_filter.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/image.hpp>
#include <impasto/render/render_painting.hpp>
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render_gl/canvas_renderer.hpp>
#include <impasto/render_gl/framebuffer.hpp>
#include <impasto/render_gl/gl_context.hpp>
#include <impasto/render_gl/render_painting_gpu.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.hpp"
#include "impasto/util/statistics.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_zoom_cmd {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchZoomArgs {
  std::string painting;
  std::vector<double> cells_per_pixel{1.0, 1.25, 1.5, 2.0, 3.0, 4.0};
  int wavelengths = render::RenderSettings{}.wavelengths;
  int frames = 3;
  std::string views;  // a prefix: each zoom's window view and reference as PNG
  bool json = false;
};

// `linear` display-encoded (sRGB) into PREFIX-window-Z.png or PREFIX-reference-Z.png.
void save_view(const render::Image& linear, const std::string& prefix, const char* what,
               double cells_per_pixel) {
  render::Image encoded = linear;
  for (float& v : encoded.rgb) v = static_cast<float>(render::srgb_encoded(v));
  char name[32];
  std::snprintf(name, sizeof name, "-%s-%.2f.png", what, cells_per_pixel);
  render::write_png(prefix + name, encoded);
}

struct Difference {
  double mean = 0.0, p99 = 0.0, max = 0.0;  // 8-bit sRGB levels
};

Difference difference(const render::Image& a, const render::Image& b) {
  std::vector<double> levels;
  levels.reserve(static_cast<std::size_t>(a.width) * a.height);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      double worst = 0.0;
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, 255.0 * std::abs(render::srgb_encoded(a.pixel(x, y)[c]) -
                                                 render::srgb_encoded(b.pixel(x, y)[c])));
      }
      levels.push_back(worst);
    }
  }
  Difference d;
  for (double v : levels) d.mean += v / static_cast<double>(levels.size());
  std::sort(levels.begin(), levels.end());
  d.p99 = levels[static_cast<std::size_t>(0.99 * static_cast<double>(levels.size() - 1))];
  d.max = levels.back();
  return d;
}

// The window's view of the whole canvas at `cells_per_pixel`, w x h pixels, rows top-down,
// linear; frame_ms gets the median of `frames` timed draws.
render::Image window_view(render_gl::CanvasRenderer& renderer, double cells_per_pixel, int w, int h,
                          int frames, double& frame_ms) {
  const render_gl::CanvasView view{0.5 * renderer.width_cells(), 0.5 * renderer.height_cells(),
                                   1.0 / cells_per_pixel, 0.0};
  render_gl::Framebuffer target(w, h, render_gl::TexelFormat::kRGBA32F);  // timed like the window's
  target.bind();
  std::vector<double> ms;
  for (int f = 0; f < frames; ++f) {
    glFinish();
    const auto start = Clock::now();
    renderer.draw(view, w, h);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  frame_ms = util::median(ms);
  return render_gl::draw_to_image(renderer, view, w, h);
}

void run(const BenchZoomArgs& args) {
  const paintcore::Painting painting = paintcore::Painting::load(args.painting);
  const paintcore::Canvas& canvas = painting.canvas();
  render::RenderSettings settings;
  settings.wavelengths = args.wavelengths;
  settings.display = render::DisplayEncoding::linear_srgb;
  settings.cracks = false;  // the supersampled reference does not carry them

  const render::Image reference =
      render::render_painting_supersampled(painting, settings, render::kMaxSupersample);
  const render::Image one_sample = render::render_painting(painting, settings);

  auto context = render_gl::create_headless_context();
  render_gl::CanvasRenderer renderer(canvas.width_cells(), canvas.height_cells(), settings,
                                     render::SpectralPalette(settings, painting));
  renderer.upload_all(canvas);

  nlohmann::json rows = nlohmann::json::array();
  if (!args.json) {
    std::printf(
        "%s, %dx%d cells, %d nodes; error against the 4x4-supersampled render "
        "box-filtered, 8-bit sRGB levels (mean / p99 / max)\n",
        args.painting.c_str(), canvas.width_cells(), canvas.height_cells(), args.wavelengths);
    std::printf("%10s %11s %22s %22s %10s\n", "cells/px", "view", "window", "cells filtered",
                "frame ms");
  }
  for (const double z : args.cells_per_pixel) {
    const int w = static_cast<int>(canvas.width_cells() / z);
    const int h = static_cast<int>(canvas.height_cells() / z);
    const render::Image truth = render::box_filtered(reference, z, w, h);
    double frame_ms = 0.0;
    const render::Image view = window_view(renderer, z, w, h, args.frames, frame_ms);
    const Difference window = difference(view, truth);
    if (!args.views.empty()) {
      save_view(view, args.views, "window", z);
      save_view(truth, args.views, "reference", z);
    }
    const Difference cells = difference(render::box_filtered(one_sample, z, w, h), truth);
    rows.push_back(
        {{"cells_per_pixel", z},
         {"view", {w, h}},
         {"window", {{"mean", window.mean}, {"p99", window.p99}, {"max", window.max}}},
         {"cells_filtered", {{"mean", cells.mean}, {"p99", cells.p99}, {"max", cells.max}}},
         {"frame_ms", frame_ms}});
    if (!args.json) {
      std::printf("%10.2f %5dx%-5d %6.2f / %5.1f / %5.1f %6.2f / %5.1f / %5.1f %10.1f\n", z, w, h,
                  window.mean, window.p99, window.max, cells.mean, cells.p99, cells.max, frame_ms);
    }
  }
  if (args.json) {
    std::cout << nlohmann::json{{"painting", args.painting},
                                {"opengl", render_gl::gl_description()},
                                {"nodes", args.wavelengths},
                                {"zooms", rows}}
                     .dump(2)
              << "\n";
  }
}

void setup(CLI::App& root) {
  auto args = std::make_shared<BenchZoomArgs>();
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "zoom", "The window zoomed out against the supersampled render box-filtered (aliasing)");
  cmd->add_option("painting", args->painting, "The .impasto painting file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--cells-per-pixel", args->cells_per_pixel, "The zooms, 1..16 cells a pixel")
      ->delimiter(',')
      ->check(finite_range(1.0, 16.0))
      ->capture_default_str();
  cmd->add_option("--frames", args->frames, "Frames to time at each zoom")
      ->check(finite_range(1, 100));
  cmd->add_option("--views", args->views,
                  "Save each zoom's window view and reference as PREFIX-window-Z.png and "
                  "PREFIX-reference-Z.png");
  add_wavelengths_option(*cmd, args->wavelengths, false, "the shaders take 1..16");
  add_json_flag(*cmd, args->json, "every zoom's errors and frame time in one object");
  cmd->callback([args] { run(*args); });
}

const CommandRegistrar registrar("bench zoom", setup);

}  // namespace
}  // namespace impasto::app::bench_zoom_cmd
