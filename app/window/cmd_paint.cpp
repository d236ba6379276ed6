// impasto paint [PAINTING]: the painting window. With --replay, --screenshot and --exit it
// runs a recorded session through the window and captures it (scripted use, tests).
#include <impasto/render/spectral_sampling.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "command.hpp"
#include "vocabulary.hpp"
#include "window/paint_options.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::paint_cmd {
namespace {

struct PaintArgs {
  std::string painting, replay, screenshot, record, reference;
  std::string quality{
      util::name_of(paintcore::kStepQualityNames, paintcore::StepQuality::balanced)};
  std::optional<CanvasSize> size;
  window::PaintOptions options;
};

void setup(CLI::App& root) {
  auto args = std::make_shared<PaintArgs>();
  CLI::App* cmd = root.add_subcommand("paint", "Open the painting window");
  cmd->add_option("painting", args->painting, "An .impasto painting to open")
      ->check(CLI::ExistingFile);
  cmd->add_option("--replay", args->replay,
                  "Replay a stroke file (native, libmypaint .dat or BDALab .svc) through the "
                  "window's input path")
      ->check(CLI::ExistingFile);
  cmd->add_option("--reference", args->reference,
                  "A picture (PNG or JPEG) to paint from, in a window of its own (View > Reference "
                  "image...)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--screenshot", args->screenshot,
                  "Save a PNG of the whole window once the replay is applied");
  cmd->add_flag("--exit", args->options.exit_after, "Quit after the replay and screenshot");
  cmd->add_option(
      "--record", args->record,
      "Record this session's input here, a new file (default: beside the painting, or in the "
      "recovery folder)");
  cmd->add_flag("--no-record", args->options.no_record,
                "Do not record this session's input (nor keep it for crash recovery)");
  cmd->add_option("--autosave-seconds", args->options.autosave_seconds,
                  "Autosave to the recovery folder at least this often while painting")
      ->check(finite_range(5.0, 86400.0));
  cmd->add_option("--window-width", args->options.window_width, "Window width in pixels")
      ->check(finite_range(320, 8192));
  cmd->add_option("--window-height", args->options.window_height, "Window height in pixels")
      ->check(finite_range(240, 8192));
  add_size_option(*cmd, args->size, "for a new canvas (default 1024x768)");
  add_dpi_option(*cmd, args->options.new_canvas.dpi, "for a new canvas");
  add_wavelengths_option(*cmd, args->options.wavelengths, false,
                         "here 1..16 (the window renders on the GPU)");
  add_quality_option(*cmd, args->quality, "to begin with (the View panel changes it)")
      ->capture_default_str();
  cmd->add_flag("--no-catch-up{false}", args->options.catch_up,
                "Keep the quality while the simulation is behind the pen (by default it takes "
                "fast steps until it has caught up)");
  add_deprecated_option(*cmd, "--width", "--size WxH", [args](const std::string& text) {
    args->options.new_canvas.width_cells = parse_canvas_size(text + "x1", "--width").width;
  });
  add_deprecated_option(*cmd, "--height", "--size WxH", [args](const std::string& text) {
    args->options.new_canvas.height_cells = parse_canvas_size("1x" + text, "--height").height;
  });
  cmd->callback([args] {
    window::PaintOptions options = args->options;
    options.quality = util::parse_name(paintcore::kStepQualityNames, args->quality, "quality");
    if (args->size) {
      options.new_canvas.width_cells = args->size->width;
      options.new_canvas.height_cells = args->size->height;
    }
    if (!args->painting.empty()) options.painting = args->painting;
    if (!args->replay.empty()) options.replay = args->replay;
    if (!args->screenshot.empty()) options.screenshot = args->screenshot;
    if (!args->reference.empty()) options.reference = args->reference;
    if (!args->record.empty()) options.record = args->record;
    window::run_paint_window(options);
  });
}

const CommandRegistrar registrar("paint", setup);

}  // namespace
}  // namespace impasto::app::paint_cmd
