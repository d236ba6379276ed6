// impasto render: a painting file to a PNG or EXR image, spectrally rendered under a light.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/crack_close_up.hpp>
#include <impasto/render/render_painting.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "command.hpp"
#include "surface_options.hpp"

// The GL path, when this build has it (render_gl's headers come with its target).
#if __has_include(<impasto/render_gl/render_painting_gpu.hpp>)
#include <impasto/render_gl/render_painting_gpu.hpp>
#define IMPASTO_RENDER_GPU 1
#endif

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::render_cmd {
namespace {

using namespace impasto::render;

struct RenderArgs {
  std::string painting;
  std::string out;
  std::string light = "D65";
  std::string wavelengths = "8";
  std::string light_dir = "225,60";
  std::string display = "srgb";
  std::string adaptation = "bradford";
  std::string weights{util::name_of(kNodeWeightsNames, RenderSettings{}.node_weights)};
  std::string storage = "float";
  double thickness_scale_mm = RenderSettings{}.thickness_scale_mm;
  bool saunderson = false;
  int threads = 0;
  std::string light_type{util::name_of(kLightTypeNames, RenderSettings{}.light_type)};
  double light_size_deg = RenderSettings{}.light_size_deg;
  double light_distance_mm = RenderSettings{}.light_distance_mm;
  bool no_flakes = false;
  std::string flake_depth = "masking";
  bool no_cracks = false;
  bool no_shadows = false;
  bool no_occlusion = false;
  std::string crack_model{util::name_of(cracks::kCavityModelNames, RenderSettings{}.crack_model)};
  double ambient = RenderSettings{}.ambient;
  bool gpu = false;    // through the GLSL shaders, headless
  int zoom = 0;        // > 0: the close-up of --region at this many pixels per cell
  std::string region;  // "X,Y,W,H" in cells
  SurfaceArgs surface;  // --surface, --medium, --varnish (docs/surface.md)
};

int parse_wavelengths(const std::string& text) {
  if (text == "full") return 0;
  std::size_t used = 0;
  int n = -1;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
  }
  if (used != text.size() || n < 1 || n > kMaxNodes) {
    throw std::runtime_error("--wavelengths " + text + ": expected 1..16 or full");
  }
  return n;
}

// "AZ,EL" in degrees.
void parse_light_dir(const std::string& text, RenderSettings& settings) {
  const auto comma = text.find(',');
  try {
    if (comma == std::string::npos) throw std::invalid_argument("no comma");
    std::size_t used_az = 0, used_el = 0;
    const std::string az = text.substr(0, comma);
    const std::string el = text.substr(comma + 1);
    settings.light_azimuth_deg = std::stod(az, &used_az);
    settings.light_elevation_deg = std::stod(el, &used_el);
    if (used_az != az.size() || used_el != el.size()) throw std::invalid_argument("junk");
  } catch (const std::exception&) {
    throw std::runtime_error("--light-dir " + text +
                             ": expected AZIMUTH,ELEVATION in degrees, e.g. 225,60");
  }
}

void run(const RenderArgs& args) {
  RenderSettings settings;
  settings.light = args.light;
  settings.wavelengths = parse_wavelengths(args.wavelengths);
  parse_light_dir(args.light_dir, settings);
  settings.display = parse_display_encoding(args.display);
  settings.adaptation = parse_chromatic_adaptation(args.adaptation);
  settings.node_weights = parse_node_weights(args.weights);
  settings.storage = parse_reflectance_storage(args.storage);
  settings.thickness_scale_mm = args.thickness_scale_mm;
  settings.saunderson = args.saunderson;
  settings.threads = args.threads;
  settings.light_type = parse_light_type(args.light_type);
  settings.light_size_deg = args.light_size_deg;
  settings.light_distance_mm = args.light_distance_mm;
  settings.flakes = !args.no_flakes;
  settings.flake_masking = args.flake_depth == "masking";
  settings.cracks = !args.no_cracks;
  settings.shadows = !args.no_shadows;
  settings.occlusion = !args.no_occlusion;
  settings.crack_model = parse_crack_model(args.crack_model);
  settings.ambient = args.ambient;
  apply_surface_options(args.surface, settings);
  validate(settings);
  const paintcore::Painting painting = paintcore::Painting::load(args.painting, args.threads);
  check_render_memory(painting.canvas(), args.painting);
  if (args.zoom > 0) {
    // The close-up: the region magnified, its cracks shaded point by point.
    const CellRegion region =
        args.region.empty()
            ? CellRegion{0, 0, painting.canvas().width_cells(), painting.canvas().height_cells()}
            : parse_cell_region(args.region);
    if (args.gpu) {
#ifdef IMPASTO_RENDER_GPU
      render_gl::render_painting_close_up_gpu_to_file(painting, settings, region, args.zoom,
                                                      args.out);
#else
      throw std::runtime_error("--gpu: this impasto was built without the OpenGL path");
#endif
    } else {
      render_painting_close_up_to_file(painting, settings, region, args.zoom, args.out);
    }
    std::cout << "wrote " << args.out << " (" << region.w * args.zoom << "x" << region.h * args.zoom
              << ", close-up)\n";
    return;
  }
  if (args.gpu) {
#ifdef IMPASTO_RENDER_GPU
    render_gl::render_painting_gpu_to_file(painting, settings, args.out);
#else
    throw std::runtime_error("--gpu: this impasto was built without the OpenGL path");
#endif
  } else {
    render_painting_to_file(painting, settings, args.out);
    write_subsurface_map_if_asked(args.surface, painting, settings);
  }
  std::cout << "wrote " << args.out << " (" << painting.canvas().width_cells() << "x"
            << painting.canvas().height_cells() << ")\n";
}

const CommandRegistrar registrar("render", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand(
      "render", "Render a painting to PNG (sRGB) or EXR (linear) under a light");
  auto args = std::make_shared<RenderArgs>();
  cmd->add_option("painting", args->painting, "The .impasto painting file")->required();
  cmd->add_option("--out,-o", args->out, "Output image, FILE.png or FILE.exr")->required();
  cmd->add_option("--light", args->light, "D65, A, F11, ..., blackbody:KELVIN or a spectral CSV")
      ->capture_default_str();
  cmd->add_option("--wavelengths", args->wavelengths, "Gaussian nodes 1..16, or full (every nm)")
      ->capture_default_str();
  cmd->add_option("--light-dir", args->light_dir,
                  "Light azimuth,elevation in degrees (azimuth from +x toward +y, down)")
      ->capture_default_str();
  cmd->add_option("--display", args->display,
                  "PNG encoding: srgb, display-p3, rec709, rec2020, linear-srgb")
      ->capture_default_str();
  cmd->add_option("--adaptation", args->adaptation, "bradford (light white -> D65) or none")
      ->capture_default_str();
  cmd->add_option("--weights", args->weights,
                  "Nodes and XYZ weights (optimised and fitted: trained on the palette)")
      ->check(CLI::IsMember(util::names_of(kNodeWeightsNames)))
      ->capture_default_str();
  cmd->add_option("--storage", args->storage, "Baked reflectance storage: float or half")
      ->capture_default_str();
  cmd->add_option("--thickness-scale", args->thickness_scale_mm,
                  "mm of paint per unit of K-M optical thickness")
      ->capture_default_str();
  cmd->add_flag("--saunderson", args->saunderson, "Apply the Saunderson surface correction");
  cmd->add_option("--light-type", args->light_type,
                  "directional (sun), point, spot, or diffuse (overcast: no sparkles)")
      ->check(CLI::IsMember(util::names_of(kLightTypeNames)))
      ->capture_default_str();
  cmd->add_option("--light-size", args->light_size_deg,
                  "Apparent diameter of the light in degrees (the sun: 0.53)")
      ->check(CLI::Range(1e-3, 90.0))
      ->capture_default_str();
  cmd->add_option("--light-distance", args->light_distance_mm,
                  "Point and spot lights: mm from the canvas centre along --light-dir")
      ->check(CLI::Range(1.0, 1e7))
      ->capture_default_str();
  cmd->add_flag("--no-flakes", args->no_flakes, "Flake pigments without their sparkles");
  cmd->add_flag("--no-cracks", args->no_cracks, "Cracked cells as if uncracked");
  cmd->add_flag("--no-shadows", args->no_shadows, "No shadows cast by the paint relief");
  cmd->add_flag("--no-occlusion", args->no_occlusion, "No ambient occlusion in furrows");
  cmd->add_option("--crack-model", args->crack_model,
                  "Cavity reflectance: corrected (measured tables) or gouffe (closed form)")
      ->check(CLI::IsMember(util::names_of(cracks::kCavityModelNames)))
      ->capture_default_str();
  cmd->add_option(
         "--ambient", args->ambient,
         "Share of the light arriving from the whole sky, 0..1 (the rest from --light-dir)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--flake-depth", args->flake_depth,
                  "Flake depth model: masking (Eq. 5) or no-masking (Eq. 6)")
      ->check(CLI::IsMember({"masking", "no-masking"}))
      ->capture_default_str();
  cmd->add_flag("--gpu", args->gpu,
                "Render through the OpenGL shaders, headless (EGL or OSMesa); 1..16 nodes");
  cmd->add_option("--zoom", args->zoom,
                  "Close-up: pixels per cell, cracks shaded inside (with --region)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--region", args->region, "Close-up region X,Y,W,H in cells (default: all)");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  add_surface_options(*cmd, args->surface);
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::render_cmd
