// impasto render: a painting file to a PNG or EXR image, spectrally rendered under a light.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/crack_close_up.hpp>
#include <impasto/render/render_painting.hpp>
#include <impasto/render/spectral_palette.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "command.hpp"
#include "progress_reporter.hpp"
#include "surface_options.hpp"
#include "vocabulary.hpp"
#include "window_services.hpp"

// The GL path, when this build has it (render_gl's headers come with its target).

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::render_cmd {
namespace {

using namespace impasto::render;

// The OpenGL path's renderers, which the window target provides.
const WindowServices& gpu() {
  const WindowServices* services = window_services();
  if (services == nullptr || !services->render_painting)
    throw std::runtime_error(std::string("--gpu: ") + kNoGpuPath);
  return *services;
}

struct RenderArgs {
  std::string painting;
  std::string out;
  std::string light = "D65";
  int wavelengths = RenderSettings{}.wavelengths;
  std::string light_dir = "225,60";
  std::string display{util::name_of(kDisplayEncodingNames, RenderSettings{}.display)};
  std::string adaptation{util::name_of(kChromaticAdaptationNames, RenderSettings{}.adaptation)};
  std::string weights{util::name_of(kNodeWeightsNames, RenderSettings{}.node_weights)};
  std::string storage{util::name_of(kReflectanceStorageNames, RenderSettings{}.storage)};
  double thickness_scale_mm = RenderSettings{}.thickness_scale_mm;
  bool no_saunderson = false;
  int threads = 0;
  std::string light_type{util::name_of(kLightTypeNames, RenderSettings{}.light_type)};
  double light_size_deg = RenderSettings{}.light_size_deg;
  double light_distance_mm = RenderSettings{}.light_distance_mm;
  bool no_flakes = false;
  std::string flake_depth{util::name_of(kFlakeDepthNames, RenderSettings{}.flake_masking)};
  bool no_cracks = false;
  bool no_shadows = false;
  bool no_occlusion = false;
  std::string crack_model{util::name_of(cracks::kCavityModelNames, RenderSettings{}.crack_model)};
  double ambient = RenderSettings{}.ambient;
  bool gpu = false;     // through the GLSL shaders, headless
  int zoom = 0;         // > 0: the close-up of --region at this many pixels per cell
  int supersample = 1;  // samples a pixel each way, box-filtered (CPU only)
  std::string region;   // "X,Y,W,H" in cells
  SurfaceArgs surface;  // --surface, --medium, --varnish (docs/surface.md)
  bool json = false;    // timings and the image's size as JSON
};

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void run(const RenderArgs& args) {
  RenderSettings settings;
  settings.light = args.light;
  settings.wavelengths = args.wavelengths;
  parse_light_direction(args.light_dir, settings);
  settings.display = parse_display_encoding(args.display);
  settings.adaptation = parse_chromatic_adaptation(args.adaptation);
  settings.node_weights = parse_node_weights(args.weights);
  settings.storage = parse_reflectance_storage(args.storage);
  settings.thickness_scale_mm = args.thickness_scale_mm;
  settings.saunderson = !args.no_saunderson;
  settings.threads = args.threads;
  settings.light_type = parse_light_type(args.light_type);
  settings.light_size_deg = args.light_size_deg;
  settings.light_distance_mm = args.light_distance_mm;
  settings.flakes = !args.no_flakes;
  settings.flake_masking = util::parse_name(kFlakeDepthNames, args.flake_depth, "flake depth");
  settings.cracks = !args.no_cracks;
  settings.shadows = !args.no_shadows;
  settings.occlusion = !args.no_occlusion;
  settings.crack_model = parse_crack_model(args.crack_model);
  settings.ambient = args.ambient;
  apply_surface_options(args.surface, settings);
  validate(settings);
  image_file_type(args.out);  // a bad extension fails now, not after the render
  if (args.supersample > 1 && (args.gpu || args.zoom > 0))
    throw std::runtime_error(
        "--supersample: the CPU render of the whole painting only (not with "
        "--gpu or --zoom)");
  const auto start = Clock::now();
  const paintcore::Painting painting = paintcore::Painting::load(args.painting, args.threads);
  // The whole canvas's render state for the GPU and the close-up; the file's render goes by
  // bands where it can, which takes less.
  if (args.gpu || args.zoom > 0)
    check_render_memory(painting.canvas(), args.painting);
  else
    check_render_to_file_memory(painting, settings, args.out, args.supersample, args.painting);
  const double load_seconds = seconds_since(start);
  const auto render_start = Clock::now();
  int width = painting.canvas().width_cells(), height = painting.canvas().height_cells();
  if (args.zoom > 0) {
    // The close-up: the region magnified, its cracks shaded point by point.
    const CellRegion region =
        args.region.empty() ? CellRegion{0, 0, width, height} : parse_cell_region(args.region);
    if (args.gpu) {
      gpu().render_close_up(painting, settings, region, args.zoom, args.out);
    } else {
      render_painting_close_up_to_file(painting, settings, region, args.zoom, args.out);
    }
    width = region.w * args.zoom;
    height = region.h * args.zoom;
  } else if (args.gpu) {
    gpu().render_painting(painting, settings, args.out);
    write_subsurface_map_if_asked(args.surface, painting, settings);
  } else {
    ProgressReporter progress("render", "tiles");
    render_painting_to_file(painting, settings, args.out, progress.callback(), args.supersample);
    write_subsurface_map_if_asked(args.surface, painting, settings);
  }
  const double render_seconds = seconds_since(render_start);
  // Which wavelengths rendered it, and why (a small palette cannot train the optimised rule).
  const SpectralSampling sampling = SpectralPalette(settings, painting).sampling();
  const std::string& rule = sampling.rule;
  if (args.json) {
    // Rendering and writing the file are one call: render_seconds holds both.
    std::cout << nlohmann::json{{"out", args.out},
                                {"width", width},
                                {"height", height},
                                {"close_up", args.zoom > 0},
                                {"gpu", args.gpu},
                                {"wavelengths", settings.wavelengths},
                                {"rule", rule},
                                {"nodes", sampling.full_spectrum ? 0 : sampling.size()},
                                {"estimated_de00",
                                 sampling.estimated_mean_de00 < 0.0
                                     ? nlohmann::json(nullptr)
                                     : nlohmann::json{{"mean", sampling.estimated_mean_de00},
                                                      {"max", sampling.estimated_max_de00}}},
                                {"load_seconds", load_seconds},
                                {"render_seconds", render_seconds}}
              << "\n";
    return;
  }
  char timing[64];
  std::snprintf(timing, sizeof timing, "%.2f s", render_seconds);
  note("wrote " + args.out + " (" + std::to_string(width) + "x" + std::to_string(height) +
       (args.zoom > 0 ? ", close-up" : "") + ", rendered in " + timing +
       "; wavelengths: " + describe_rule(sampling) + ")");
}

const CommandRegistrar registrar("render", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand(
      "render", "Render a painting to PNG (sRGB) or EXR (linear) under a light");
  auto args = std::make_shared<RenderArgs>();
  cmd->add_option("painting", args->painting, "The .impasto painting file")
      ->required()
      ->check(CLI::ExistingFile);
  add_out_option(*cmd, args->out, "the image, FILE.png (sRGB) or FILE.exr (linear)")->required();
  add_json_flag(*cmd, args->json,
                "the image's size and the seconds taken to load and to render and write");
  cmd->add_option("--light", args->light, vocabulary_help("--light"))->capture_default_str();
  add_wavelengths_option(*cmd, args->wavelengths, true, "--gpu: 1..16");
  add_light_dir_option(*cmd, args->light_dir);
  add_choice_option(*cmd, "--light-type", args->light_type, kLightTypeNames,
                    "The light's kind (diffuse: overcast, no sparkles)");
  cmd->add_option("--light-size", args->light_size_deg,
                  "Apparent diameter of the light in degrees (the sun: 0.53)")
      ->check(finite_range(1e-3, 90.0))
      ->capture_default_str();
  cmd->add_option("--light-distance", args->light_distance_mm,
                  "Point and spot lights: mm from the canvas centre along --light-dir")
      ->check(finite_range(1.0, 1e7))
      ->capture_default_str();
  cmd->add_option("--ambient", args->ambient,
                  "Share of the light arriving from the whole sky, 0..1 (the rest from "
                  "--light-dir)")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  add_choice_option(*cmd, "--display", args->display, kDisplayEncodingNames,
                    "The PNG's encoding (an EXR is always linear-srgb)");
  add_choice_option(*cmd, "--adaptation", args->adaptation, kChromaticAdaptationNames,
                    "Chromatic adaptation (bradford: the light's white shows as D65 white)");
  add_choice_option(*cmd, "--weights", args->weights, kNodeWeightsNames,
                    "Nodes and XYZ weights (optimised and fitted: trained on the palette)");
  add_choice_option(*cmd, "--storage", args->storage, kReflectanceStorageNames,
                    "Baked reflectance storage");
  cmd->add_option("--thickness-scale", args->thickness_scale_mm,
                  "mm of paint per unit of K-M optical thickness")
      ->capture_default_str();
  cmd->add_flag("--no-saunderson", args->no_saunderson,
                "The bare K-M reflectance, without the paint's surface over it (Saunderson)");
  cmd->add_flag("--no-flakes", args->no_flakes, "Flake pigments without their sparkles");
  add_choice_option(*cmd, "--flake-depth", args->flake_depth, kFlakeDepthNames,
                    "Flake depth model (docs/flakes.md: Eq. 5 or Eq. 6)");
  cmd->add_flag("--no-cracks", args->no_cracks, "Cracked cells as if uncracked");
  add_choice_option(*cmd, "--crack-model", args->crack_model, cracks::kCavityModelNames,
                    "Cavity reflectance (corrected: the measured tables; gouffe: closed form)");
  cmd->add_flag("--no-shadows", args->no_shadows, "No shadows cast by the paint relief");
  cmd->add_flag("--no-occlusion", args->no_occlusion, "No ambient occlusion in furrows");
  cmd->add_flag("--gpu", args->gpu,
                "Render through the OpenGL shaders, headless (EGL or OSMesa); 1..16 nodes");
  cmd->add_option("--zoom", args->zoom,
                  "Close-up: pixels per cell, cracks shaded inside (with --region)")
      ->check(finite_range(1, 256));
  cmd->add_option("--region", args->region, "Close-up region X,Y,W,H in cells (default: all)");
  cmd->add_option("--supersample", args->supersample,
                  "Samples a pixel each way (1, 2, 4): shaded that much finer and box-filtered "
                  "in linear light, so weave and furrows finer than a pixel do not alias")
      ->check(finite_range(1, render::kMaxSupersample))
      ->capture_default_str();
  add_threads_option(*cmd, args->threads);
  add_surface_options(*cmd, args->surface);
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::render_cmd
