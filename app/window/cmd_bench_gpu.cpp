// impasto bench gpu: what the painting window costs on this machine's OpenGL — the frame
// time of a large canvas (whole, and as the window's cached view shows it), and the latency
// from one pen sample to the updated frame, with and without the view cache.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render_gl/canvas_renderer.hpp>
#include <impasto/render_gl/framebuffer.hpp>
#include <impasto/render_gl/gl_context.hpp>
#include <impasto/render_gl/shaded_view_cache.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "command.hpp"
#include "impasto/util/statistics.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_gpu_cmd {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

using util::median;

struct BenchGpuArgs {
  std::optional<CanvasSize> size;  // the frame time's canvas (default 4096x4096)
  int frames = 5;
  int viewport_w = 1400;  // the window's canvas view for the latency
  int viewport_h = 900;
  int brush_px = 128;  // brush width in cells for the latency
  int samples = 20;
  int wavelengths = render::RenderSettings{}.wavelengths;
  bool json = false;
};

// A painting with four pigment slots: the shader runs its per-slot loops for every pixel,
// painted or not, so the frame time does not depend on where the paint is.
paintcore::Painting striped_painting(int width, int height, int slots) {
  paintcore::Painting painting({width, height, 300.0, 1});
  const char* names[] = {"White", "Blue Red Shade", "Red", "Cold Yellow"};
  for (int s = 0; s < slots; ++s) painting.slot_for(names[s]);
  return painting;
}

void run(const BenchGpuArgs& args) {
  const CanvasSize canvas = args.size.value_or(CanvasSize{4096, 4096});
  const int width = canvas.width, height = canvas.height;
  auto context = render_gl::create_headless_context();
  // Under --json the sentences below go nowhere and the numbers into one object.
  std::ostringstream unused;
  std::ostream& text = args.json ? unused : std::cout;
  nlohmann::json report{{"opengl", render_gl::gl_description()},
                        {"backend", context->backend_name()},
                        {"latency", nlohmann::json::array()}};
  text << "OpenGL: " << render_gl::gl_description() << " (" << context->backend_name() << ")\n";
  render::RenderSettings settings;
  settings.wavelengths = args.wavelengths;

  // 1. A full frame of the canvas, one pixel per cell.
  {
    paintcore::Painting painting = striped_painting(width, height, 4);
    painting.set_brush({"round", 20.0, 0.5});
    painting.load_brush({{"Blue Red Shade", 1.0}, {"White", 1.0}}, 400.0);
    painting.begin_stroke();
    for (int i = 0; i <= 20; ++i) {
      paintcore::PenSample sample;
      sample.time_s = 0.01 * i;
      sample.x_mm = 10.0 + 4.0 * i;
      sample.y_mm = 40.0;
      sample.pressure = 0.8f;
      sample.buttons = paintcore::kPenTip;
      painting.stroke_to(sample);
    }
    painting.end_stroke();
    render::SpectralPalette palette(settings, painting.pigment_slots());
    const auto upload_start = Clock::now();
    render_gl::CanvasRenderer renderer(width, height, settings, palette);
    renderer.upload_all(painting.canvas());
    glFinish();
    const double upload_ms = ms_since(upload_start);
    render_gl::Framebuffer target(width, height, render_gl::TexelFormat::kRGBA8);
    std::vector<double> frame_ms;
    for (int f = 0; f < args.frames; ++f) {
      target.bind();
      const auto start = Clock::now();
      renderer.draw(render_gl::one_pixel_per_cell(width, height), width, height);
      glFinish();
      frame_ms.push_back(ms_since(start));
    }
    report["frame"] = {{"width", width},
                       {"height", height},
                       {"nodes", args.wavelengths},
                       {"median_ms", median(frame_ms)},
                       {"frames", args.frames},
                       {"upload_ms", upload_ms}};
    text << "frame " << width << "x" << height << " cells, " << args.wavelengths
         << " nodes, 4 pigments: median " << median(frame_ms) << " ms over " << args.frames
         << " frames (first upload of all tiles " << upload_ms << " ms)\n";
  }

  // 2. The window's view of that canvas, fitted (zoomed out, about 0.2 px a cell): a frame
  //    after a zoom re-shades every pixel; a pan by whole pixels moves the cached image and
  //    shades the strip it uncovers; a frame with nothing new copies the cache.
  {
    paintcore::Painting painting = striped_painting(width, height, 4);
    render::SpectralPalette palette(settings, painting.pigment_slots());
    render_gl::CanvasRenderer renderer(width, height, settings, palette);
    renderer.upload_all(painting.canvas());
    render_gl::Framebuffer target(args.viewport_w, args.viewport_h, render_gl::TexelFormat::kRGBA8);
    render_gl::CanvasView view =
        render_gl::fit_canvas(width, height, args.viewport_w, args.viewport_h);
    render_gl::ShadedViewCache cache;
    std::vector<double> full_ms, coarse_ms, pan_ms, cached_ms;
    // The coarse first frame's parts: its shading, and the rest (magnifying, the copy).
    std::vector<double> coarse_shade_ms, coarse_rest_ms, coarse_factors;
    const auto timed_draw = [&](std::vector<double>& into,
                                render_gl::ShadedViewCache::Detail detail) {
      const auto start = Clock::now();
      const render_gl::CachedDrawStats stats =
          cache.update(renderer, view, args.viewport_w, args.viewport_h, detail);
      cache.copy_to(target.id(), {0, 0, args.viewport_w, args.viewport_h});
      glFinish();
      into.push_back(ms_since(start));
      if (stats.coarse) {
        coarse_shade_ms.push_back(stats.shade_ms);
        coarse_rest_ms.push_back(into.back() - stats.shade_ms);
        coarse_factors.push_back(stats.coarse_factor);
      }
    };
    using Detail = render_gl::ShadedViewCache::Detail;
    // The window's refinement once the motion stops: a few blocks a frame.
    std::vector<double> block_ms, refine_frames;
    cache.update(renderer, view, args.viewport_w, args.viewport_h);  // the window's first frame
    for (int f = 0; f < args.frames; ++f) {
      view.pixels_per_cell *= 1.01;            // a zoom step: every pixel
      timed_draw(coarse_ms, Detail::kCoarse);  // the window's first frame of a motion
      for (int frame = 1;; ++frame) {          // refined when the motion stops
        const auto start = Clock::now();
        const render_gl::CachedDrawStats stats =
            cache.update(renderer, view, args.viewport_w, args.viewport_h, Detail::kRefining);
        for (const render_gl::PixelRect& r : stats.changed) cache.copy_to(target.id(), r);
        glFinish();
        block_ms.push_back(ms_since(start));
        if (!stats.refining) {
          refine_frames.push_back(frame);
          break;
        }
      }
      view.pixels_per_cell /= 1.01;  // the step back
      timed_draw(coarse_ms, Detail::kCoarse);
      timed_draw(full_ms, Detail::kFull);                  // refined whole, as a screenshot is
      view.center_x_cells += 10.0 / view.pixels_per_cell;  // a pan by 10 whole pixels
      timed_draw(pan_ms, Detail::kFull);
      timed_draw(cached_ms, Detail::kFull);  // nothing new
    }
    report["view"] = {{"width", args.viewport_w},
                      {"height", args.viewport_h},
                      {"pixels_per_cell", view.pixels_per_cell},
                      {"zoom_ms", median(full_ms)},
                      {"zoom_coarse_ms", median(coarse_ms)},
                      {"zoom_coarse_shading_ms", median(coarse_shade_ms)},
                      {"zoom_coarse_magnify_copy_ms", median(coarse_rest_ms)},
                      {"zoom_coarse_factor", median(coarse_factors)},
                      {"refine_block_ms", median(block_ms)},
                      {"refine_block_max_ms", *std::max_element(block_ms.begin(), block_ms.end())},
                      {"refine_frames", median(refine_frames)},
                      {"pan_ms", median(pan_ms)},
                      {"unchanged_ms", median(cached_ms)}};
    text << "window view " << args.viewport_w << "x" << args.viewport_h << " of the " << width
         << "x" << height << " canvas, fitted (" << view.pixels_per_cell
         << " px/cell): after a zoom or light change median " << median(full_ms)
         << " ms (first frame while moving, coarse: " << median(coarse_ms)
         << " ms, its parts' medians: shading " << median(coarse_shade_ms) << " ms at 1/"
         << median(coarse_factors) << " resolution, magnifying and copy " << median(coarse_rest_ms)
         << " ms; refined in blocks over " << median(refine_frames) << " frames of median "
         << median(block_ms) << " ms, at most "
         << *std::max_element(block_ms.begin(), block_ms.end()) << " ms), after a 10-px pan "
         << median(pan_ms) << " ms, unchanged " << median(cached_ms) << " ms\n";
  }

  // 3. Pen sample to updated frame with a brush_px-wide brush: simulation step, dirty tiles
  //    to the GPU, the window-sized view redrawn (glFinish: the frame is done). "Whole view"
  //    re-shades every pixel of the view per frame; "cached" re-shades only the changed tiles'
  //    pixels (the window's way).
  const auto latency = [&](double pixels_per_cell, bool cached) {
    const int size = 2048;
    paintcore::Painting painting({size, size, 300.0, 1});
    const double cell_mm = painting.canvas().cell_mm();
    painting.set_brush({"round", args.brush_px * cell_mm, 0.5});
    painting.load_brush({{"Red", 1.0}, {"White", 1.0}}, 20000.0);
    render::SpectralPalette palette(settings, painting.pigment_slots());
    render_gl::CanvasRenderer renderer(size, size, settings, palette);
    renderer.upload_all(painting.canvas());
    const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
    (void)painting.take_changes(changes);  // the canvas as uploaded
    render_gl::Framebuffer target(args.viewport_w, args.viewport_h, render_gl::TexelFormat::kRGBA8);
    const render_gl::CanvasView view{size / 2.0, size / 2.0, pixels_per_cell, 0.0};
    render_gl::ShadedViewCache cache;
    cache.draw(renderer, view, args.viewport_w, args.viewport_h, target.id());
    std::vector<double> sim_ms, upload_ms, draw_ms, total_ms;
    long long shaded = 0;
    painting.begin_stroke();
    for (int i = 0; i < args.samples; ++i) {
      paintcore::PenSample sample;
      sample.time_s = 0.008 * i;
      sample.x_mm = (size / 2.0 - 300 + 8.0 * i) * cell_mm;  // 8 cells per sample, ~125 Hz
      sample.y_mm = size / 2.0 * cell_mm;
      sample.pressure = 0.7f;
      sample.buttons = paintcore::kPenTip;
      const auto start = Clock::now();
      painting.stroke_to(sample);
      const auto simulated = Clock::now();
      const std::vector<int> dirty = paintcore::tile_indices(painting.take_changes(changes));
      renderer.upload_tiles(painting.canvas(), dirty);
      const auto uploaded = Clock::now();
      if (cached) {
        cache.invalidate_tiles(dirty);
        shaded +=
            cache.draw(renderer, view, args.viewport_w, args.viewport_h, target.id()).pixels_shaded;
      } else {
        target.bind();
        renderer.draw(view, args.viewport_w, args.viewport_h);
        shaded += static_cast<long long>(args.viewport_w) * args.viewport_h;
      }
      glFinish();
      if (i == 0) continue;  // the first sample only places the brush
      sim_ms.push_back(std::chrono::duration<double, std::milli>(simulated - start).count());
      upload_ms.push_back(std::chrono::duration<double, std::milli>(uploaded - simulated).count());
      draw_ms.push_back(ms_since(uploaded));
      total_ms.push_back(ms_since(start));
    }
    painting.end_stroke();
    report["latency"].push_back({{"brush_cells", args.brush_px},
                                 {"pixels_per_cell", pixels_per_cell},
                                 {"cached", cached},
                                 {"median_ms", median(total_ms)},
                                 {"simulation_ms", median(sim_ms)},
                                 {"upload_ms", median(upload_ms)},
                                 {"draw_ms", median(draw_ms)},
                                 {"pixels_shaded_per_frame", shaded / args.samples},
                                 {"samples", total_ms.size()}});
    text << "latency, pen sample to frame, " << args.brush_px << "-cell brush, " << args.viewport_w
         << "x" << args.viewport_h << " view at " << pixels_per_cell << " px/cell, "
         << (cached ? "cached" : "whole view re-shaded") << ": median " << median(total_ms)
         << " ms (simulation " << median(sim_ms) << ", upload " << median(upload_ms) << ", draw "
         << median(draw_ms) << "; " << shaded / args.samples << " px shaded a frame) over "
         << total_ms.size() << " samples\n";
  };
  for (const double zoom : {1.0, 0.25}) {
    latency(zoom, false);
    latency(zoom, true);
  }
  if (args.json) std::cout << report.dump(2) << "\n";
}

void setup(CLI::App& root) {
  auto args = std::make_shared<BenchGpuArgs>();
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand("gpu", "Frame time and pen-to-frame latency on OpenGL");
  add_size_option(*cmd, args->size, "of the frame time's canvas (default 4096x4096)", true)
      ->check(CLI::Validator(
          [](std::string& text) {
            const CanvasSize size = parse_canvas_size(text);
            return size.width >= 64 && size.height >= 64 && size.width <= 16384 &&
                           size.height <= 16384
                       ? std::string()
                       : std::string("64..16384 cells a side");
          },
          ""));
  cmd->add_option("--frames", args->frames, "Frames to time")->check(finite_range(1, 1000));
  cmd->add_option("--brush", args->brush_px, "Brush width in cells for the latency")
      ->check(finite_range(4, 1000));
  cmd->add_option("--samples", args->samples, "Pen samples to time")->check(finite_range(2, 10000));
  add_wavelengths_option(*cmd, args->wavelengths, false, "the shaders take 1..16");
  add_json_flag(*cmd, args->json, "the frame, view and latency medians in one object");
  cmd->callback([args] { run(*args); });
}

const CommandRegistrar registrar("bench gpu", setup);

}  // namespace
}  // namespace impasto::app::bench_gpu_cmd
