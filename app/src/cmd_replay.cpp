// impasto replay: paint a recorded session headless.
#include <impasto/input/stroke_import.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "session/preview.hpp"
#include "session/rebuild.hpp"
#include "session/replay.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::replay_cmd {
namespace {

struct ReplayArgs {
  std::string strokes;
  std::optional<double> dpi;
  std::string size;
  std::vector<std::string> params;
  int threads = 0;
  double source_dpi = 150.0;
  bool no_auto_load = false;
  std::string out, preview, png, light = "D65";
  int wavelengths = 8;
  std::string light_type{
      util::name_of(render::kLightTypeNames, render::RenderSettings{}.light_type)};
  double light_size_deg = render::RenderSettings{}.light_size_deg;
  bool stats = false;
};

// "WxH" in cells.
void parse_size(const std::string& text, ReplayOptions& options) {
  const auto x = text.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    std::size_t used_w = 0, used_h = 0;
    const int w = std::stoi(text.substr(0, x), &used_w);
    const int h = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("junk");
    options.width_cells = w;
    options.height_cells = h;
  } catch (const std::logic_error&) {
    throw std::runtime_error("--size: expected WIDTHxHEIGHT in cells, got '" + text + "'");
  }
}

void run_replay(const ReplayArgs& args) {
  ReplayOptions options;
  options.dpi = args.dpi;
  if (!args.size.empty()) parse_size(args.size, options);
  options.threads = args.threads;
  for (const std::string& assignment : args.params)
    paintcore::set_param(options.params, assignment);
  options.auto_load = !args.no_auto_load;
  input::ImportOptions import;
  import.source_dpi = args.source_dpi;
  const input::StrokeFile file = input::load_strokes_any(args.strokes, import);

  for (const auto& warning : file.warnings) std::cerr << "impasto: warning: " << warning << "\n";
  // A window session names the painting it began from and marks its saves: rebuild from
  // them (rebuild.hpp), unless the canvas is forced, which means a blank one.
  const bool marked = std::any_of(file.events.begin(), file.events.end(), [](const auto& e) {
    return std::holds_alternative<input::OriginEvent>(e) ||
           std::holds_alternative<input::SavedEvent>(e);
  });
  std::optional<RebuiltSession> rebuilt;
  if (marked && !options.width_cells && !options.height_cells && !options.dpi) {
    rebuilt.emplace(rebuild_session(file, options));
    for (const auto& warning : rebuilt->warnings) {
      if (std::find(file.warnings.begin(), file.warnings.end(), warning) == file.warnings.end())
        std::cerr << "impasto: warning: " << warning << "\n";
    }
  }
  ReplayReport report;
  paintcore::Painting painting =
      rebuilt ? std::move(rebuilt->painting) : replay(file, options, &report);
  if (rebuilt) report = rebuilt->report;
  if (!args.out.empty()) painting.save(args.out);
  if (!args.preview.empty()) render::write_png(args.preview, render_preview(painting));
  if (!args.png.empty()) {
    render::RenderSettings settings;
    settings.light = args.light;
    settings.wavelengths = args.wavelengths;
    settings.threads = args.threads;
    settings.light_type = render::parse_light_type(args.light_type);
    settings.light_size_deg = args.light_size_deg;
    render::render_painting_to_file(painting, settings, args.png);
  }
  if (args.stats) std::cout << replay_stats(painting, report).dump() << "\n";
}

const CommandRegistrar registrar("replay", [](CLI::App& root) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = root.add_subcommand(
      "replay", "Replay a stroke file (.strokes, libmypaint .dat, BDALab .svc) headless");
  cmd->add_option("strokes", args->strokes, "Stroke file to replay")->required();
  cmd->add_option("--dpi", args->dpi, "Canvas resolution in cells per inch")
      ->check(CLI::Range(1.0, 20000.0));
  cmd->add_option("--size", args->size, "Canvas size in cells, WIDTHxHEIGHT");
  cmd->add_option("--param", args->params,
                  "Set a paint model constant, NAME=VALUE (docs/simulation.md lists them); "
                  "repeatable");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 256));
  cmd->add_option("--source-dpi", args->source_dpi,
                  "Pixels per inch of a libmypaint .dat recording")
      ->check(CLI::Range(1.0, 20000.0));
  cmd->add_flag("--no-auto-load", args->no_auto_load,
                "Do not load the brush for recordings that carry no paint");
  cmd->add_option("--out", args->out, "Save the painting (.impasto)");
  cmd->add_option("--preview", args->preview, "Write a false-colour relief preview (.png)");
  cmd->add_option("--png", args->png,
                  "Render the painting in true colour (spectral Kubelka-Munk) to .png or .exr");
  cmd->add_option("--light", args->light, "Light for --png: D65, A, F11, blackbody:5600, FILE.csv");
  cmd->add_option("--wavelengths", args->wavelengths,
                  "Gaussian quadrature nodes for --png (1-16; 0: every nm)")
      ->check(CLI::Range(0, 16));
  cmd->add_option("--light-type", args->light_type,
                  "Light for --png: directional (sun), point, spot or diffuse (no sparkles)")
      ->check(CLI::IsMember(util::names_of(render::kLightTypeNames)));
  cmd->add_option("--light-size", args->light_size_deg,
                  "Apparent diameter of the light for --png, degrees (the sun: 0.53)")
      ->check(CLI::Range(1e-3, 90.0));
  cmd->add_flag("--stats", args->stats, "Print statistics as one JSON object");
  cmd->callback([args] { run_replay(*args); });
});

}  // namespace
}  // namespace impasto::app::replay_cmd
