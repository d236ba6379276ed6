// impasto replay: paint a recorded session headless.
#include <impasto/input/stroke_import.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "impasto/session/preview.hpp"
#include "impasto/session/rebuild.hpp"
#include "impasto/session/replay.hpp"
#include "progress_reporter.hpp"
#include "replay_overrides.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::replay_cmd {
namespace {

struct ReplayArgs {
  std::string strokes;
  std::optional<double> dpi;
  std::optional<CanvasSize> size;
  std::vector<std::string> params;
  std::string quality;  // empty: the recording's own
  int threads = 0;
  double source_dpi = 150.0;
  bool no_auto_load = false;
  std::string save, out, preview, light = "D65";
  std::string old_png;  // --png, the old spelling of --out
  int wavelengths = render::RenderSettings{}.wavelengths;
  std::string weights{
      util::name_of(render::kNodeWeightsNames, render::RenderSettings{}.node_weights)};
  std::string light_type{
      util::name_of(render::kLightTypeNames, render::RenderSettings{}.light_type)};
  double light_size_deg = render::RenderSettings{}.light_size_deg;
  bool json = false;
};

bool is_painting_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".impasto";
}

// The old command line's --out was the painting and --png the image; scripts still pass them.
void apply_old_spellings(ReplayArgs& args) {
  if (!args.out.empty() && is_painting_file(args.out)) {
    warn("--out " + args.out +
         ": --out is now the rendered image; the painting (.impasto) goes to --save");
    if (!args.save.empty() && args.save != args.out)
      throw std::runtime_error("--out " + args.out + " and --save " + args.save +
                               ": two paintings; give --save only");
    args.save = args.out;
    args.out.clear();
  }
  if (!args.old_png.empty()) {
    if (!args.out.empty() && args.out != args.old_png)
      throw std::runtime_error("--png " + args.old_png + " and --out " + args.out +
                               ": two images; give -o/--out only");
    args.out = args.old_png;
  }
  if (!args.save.empty() && !is_painting_file(args.save))
    throw std::runtime_error("--save " + args.save + ": a painting is saved as FILE.impasto");
}

std::string canvas_words(const paintcore::Painting& painting) {
  char text[96];
  std::snprintf(text, sizeof text, "%dx%d cells at %.4g dpi", painting.canvas().width_cells(),
                painting.canvas().height_cells(), 25.4 / painting.canvas().cell_mm());
  return text;
}

void run_replay(ReplayArgs args) {
  apply_old_spellings(args);
  // Bad outputs fail now, not after the replay.
  if (!args.out.empty()) render::image_file_type(args.out);
  session::ReplayOptions options = replay_options(args.size, args.dpi, args.threads, args.params);
  options.auto_load = !args.no_auto_load;
  if (!args.quality.empty())
    options.quality = util::parse_name(paintcore::kStepQualityNames, args.quality, "quality");
  input::ImportOptions import;
  import.source_dpi = args.source_dpi;
  const input::StrokeFile file = input::load_strokes_any(args.strokes, import);
  for (const auto& warning : file.warnings) warn(warning);

  ProgressReporter replay_progress("replay", "records");
  options.progress = replay_progress.callback();
  // A window session names the painting it began from and marks its saves: rebuild from
  // them (rebuild.hpp), unless the canvas is forced, which means a blank one.
  const bool marked = std::any_of(file.events.begin(), file.events.end(), [](const auto& e) {
    return std::holds_alternative<input::OriginEvent>(e) ||
           std::holds_alternative<input::SavedEvent>(e);
  });
  std::optional<session::RebuiltSession> rebuilt;
  if (marked && !options.width_cells && !options.height_cells && !options.dpi) {
    rebuilt.emplace(rebuild_session(file, options));
    for (const auto& warning : rebuilt->warnings) {
      if (std::find(file.warnings.begin(), file.warnings.end(), warning) == file.warnings.end())
        warn(warning);
    }
  }
  session::ReplayReport report;
  paintcore::Painting painting =
      rebuilt ? std::move(rebuilt->painting) : replay(file, options, &report);
  if (rebuilt) report = rebuilt->report;
  replay_progress.finish();

  // Under --json standard output holds the JSON alone.
  const auto say = [&](const std::string& text) {
    if (!args.json) note(text);
  };
  char summary[160];
  std::snprintf(summary, sizeof summary, "%llu strokes, %llu pen samples in %.2f s",
                static_cast<unsigned long long>(report.strokes),
                static_cast<unsigned long long>(report.samples), report.seconds);
  say("replayed " + args.strokes + (rebuilt ? " (from " + rebuilt->base + ")" : "") + ": " +
      summary + ", " + canvas_words(painting));
  if (!args.save.empty()) {
    painting.save(args.save);
    say("wrote " + args.save);
  }
  if (!args.preview.empty()) {
    render::write_png(args.preview, session::render_preview(painting));
    say("wrote " + args.preview + " (relief preview)");
  }
  if (!args.out.empty()) {
    render::RenderSettings settings;
    settings.light = args.light;
    settings.wavelengths = args.wavelengths;
    settings.node_weights = render::parse_node_weights(args.weights);
    settings.threads = args.threads;
    settings.light_type = render::parse_light_type(args.light_type);
    settings.light_size_deg = args.light_size_deg;
    ProgressReporter render_progress("render", "tiles");
    render::render_painting_to_file(painting, settings, args.out, render_progress.callback());
    render_progress.finish();
    say("wrote " + args.out);
  }
  if (args.json) {
    std::cout << replay_stats(painting, report).dump() << "\n";
  } else if (args.save.empty() && args.preview.empty() && args.out.empty()) {
    say("nothing written: -o FILE.png renders the painting, --save FILE.impasto keeps it, "
        "--preview FILE.png shows its relief, --json prints its statistics");
  }
}

const CommandRegistrar registrar("replay", [](CLI::App& root) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = root.add_subcommand(
      "replay",
      "Replay a stroke file (.strokes, libmypaint .dat, BDALab .svc) headless: say what it "
      "painted, and render, save or measure the painting");
  cmd->add_option("strokes", args->strokes, "Stroke file to replay")
      ->required()
      ->check(CLI::ExistingFile);
  add_out_option(*cmd, args->out,
                 "the painting in true colour (spectral Kubelka-Munk), FILE.png (sRGB) or "
                 "FILE.exr (linear)");
  add_save_option(*cmd, args->save);
  cmd->add_option("--preview", args->preview, "Write a false-colour relief preview")
      ->type_name("FILE.png");
  add_json_flag(*cmd, args->json, "the painting's statistics (docs/replay.md)");
  add_size_option(*cmd, args->size, "a blank canvas instead of the recording's");
  add_dpi_option(*cmd, args->dpi, "a blank canvas instead of the recording's");
  cmd->add_option("--param", args->params, vocabulary_help("--param"));
  add_quality_option(*cmd, args->quality,
                     "every stroke, whatever the recording's quality records say (balanced "
                     "where it has none)");
  add_threads_option(*cmd, args->threads);
  cmd->add_option("--source-dpi", args->source_dpi,
                  "Pixels per inch of a libmypaint .dat recording")
      ->check(finite_range(1.0, 20000.0))
      ->capture_default_str();
  cmd->add_flag("--no-auto-load", args->no_auto_load,
                "Do not load the brush for recordings that carry no paint");
  cmd->add_option("--light", args->light, vocabulary_help("--light", "for --out"))
      ->capture_default_str();
  add_wavelengths_option(*cmd, args->wavelengths, true, "for --out");
  add_choice_option(
      *cmd, "--weights", args->weights, render::kNodeWeightsNames,
      "Nodes and XYZ weights for --out (optimised and fitted: trained on the palette)");
  add_choice_option(*cmd, "--light-type", args->light_type, render::kLightTypeNames,
                    "The light's kind for --out (diffuse: no sparkles)");
  cmd->add_option("--light-size", args->light_size_deg,
                  "Apparent diameter of the light for --out, degrees (the sun: 0.53)")
      ->check(finite_range(1e-3, 90.0))
      ->capture_default_str();
  add_deprecated_option(*cmd, "--png", "-o/--out",
                        [args](const std::string& file) { args->old_png = file; });
  add_deprecated_flag(*cmd, "--stats", "--json", [args] { args->json = true; });
  cmd->callback([args] { run_replay(*args); });
});

}  // namespace
}  // namespace impasto::app::replay_cmd
