// impasto timelapse: a recorded session's growth as a video (MP4, WebM or GIF), relit at will.
#include <impasto/input/stroke_import.hpp>
#include <impasto/render/render_settings.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "impasto/session/timelapse.hpp"
#include "progress_reporter.hpp"
#include "replay_overrides.hpp"
#include "surface_options.hpp"
#include "timelapse_video.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::timelapse_cmd {
namespace {

struct TimelapseArgs {
  std::string strokes;
  std::string out;
  std::optional<CanvasSize> size;        // the canvas, as replay's
  std::optional<double> dpi;             // the canvas, as replay's
  std::optional<CanvasSize> frame_size;  // the video's pixels
  double fps = 30.0;
  double seconds = 10.0;
  bool real_time = false;
  double hold = 2.0;
  std::string light = "D65";
  int wavelengths = render::RenderSettings{}.wavelengths;
  std::string light_dir = "225,60";
  std::optional<double> light_turn_to;
  SurfaceArgs surface;  // --surface, --medium, --varnish (docs/surface.md)
  std::vector<std::string> params;
  int threads = 0;
};

void run(const TimelapseArgs& args) {
  const session::ReplayOptions replay =
      replay_options(args.size, args.dpi, args.threads, args.params);
  const input::StrokeFile file = input::load_strokes_any(args.strokes, input::ImportOptions{});
  for (const auto& warning : file.warnings) warn(warning);

  session::TimelapseOptions options;
  options.fps = args.fps;
  options.growth_seconds = args.seconds;
  options.real_time = args.real_time;
  options.hold_seconds = args.hold;
  options.settings.light = args.light;
  options.settings.wavelengths = args.wavelengths;
  options.settings.threads = args.threads;
  parse_light_direction(args.light_dir, options.settings);
  apply_surface_options(args.surface, options.settings);
  options.light_azimuth_end_deg = args.light_turn_to;
  render::validate(options.settings);
  ProgressReporter progress("time-lapse", "frames");
  options.progress = progress.callback();

  const TimelapseVideo video =
      write_timelapse_video(file, replay, options, args.out, args.frame_size);
  progress.finish();
  for (const auto& warning : video.report.warnings) warn(warning);
  note(timelapse_summary(video, args.out, args.fps));
}

const CommandRegistrar registrar("timelapse", [](CLI::App& root) {
  auto args = std::make_shared<TimelapseArgs>();
  CLI::App* cmd = root.add_subcommand(
      "timelapse",
      "A recorded session's growth as a video (MP4 H.264, WebM VP9 or GIF), relit at will");
  cmd->add_option("strokes", args->strokes,
                  "The session's stroke file (.strokes, libmypaint .dat, BDALab .svc)")
      ->required()
      ->check(CLI::ExistingFile);
  add_out_option(*cmd, args->out, "the video, FILE.mp4, FILE.webm or FILE.gif")->required();
  cmd->add_option_function<std::string>(
         "--frame-size",
         [args](const std::string& text) {
           args->frame_size = parse_canvas_size(text, "--frame-size");
         },
         "The video's size in pixels, WIDTHxHEIGHT (default: the canvas's cells; rounded "
         "down to even)")
      ->type_name("WxH");
  cmd->add_option("--fps", args->fps, "Frames a second")
      ->check(finite_range(1.0, 240.0))
      ->capture_default_str();
  cmd->add_option("--seconds", args->seconds,
                  "Seconds the session's pen samples are spread evenly over")
      ->check(finite_range(0.05, 3600.0))
      ->capture_default_str();
  cmd->add_flag("--real-time", args->real_time,
                "At the session's own pace instead (its samples' times, pauses kept)");
  cmd->add_option("--hold", args->hold, "Seconds the finished painting is held at the end")
      ->check(finite_range(0.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--light", args->light, vocabulary_help("--light"))->capture_default_str();
  add_wavelengths_option(*cmd, args->wavelengths, false, "");
  add_light_dir_option(*cmd, args->light_dir);
  cmd->add_option("--light-turn-to", args->light_turn_to,
                  "The light's azimuth at the last frame, degrees: it turns from --light-dir's "
                  "over the video (every frame then re-shades the whole canvas)")
      ->check(finite_range(-3600.0, 3600.0));
  add_surface_options(*cmd, args->surface, false);
  add_size_option(*cmd, args->size, "a blank canvas instead of the recording's");
  add_dpi_option(*cmd, args->dpi, "a blank canvas instead of the recording's");
  cmd->add_option("--param", args->params, vocabulary_help("--param"));
  add_threads_option(*cmd, args->threads);
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::timelapse_cmd
