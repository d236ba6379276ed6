// impasto bench window: what a user waits for in the painting window — the time from each
// mouse event's own timestamp to the buffer swap that shows it — measured with real X events
// (xdotool) sent to `impasto paint` on the current DISPLAY (Xvfb with llvmpipe, or a desktop).
// The window keeps the figures (InputLatency) and prints them when SIGTERM closes it
// (latency_lines.hpp). With --zoom, wheel clicks instead: from each click's own time to the
// swap of the first frame showing its zoom step; with --rotate, right-button drags that turn
// the view, and with --light-drag, drags of the Light panel's disc: from each move's own time
// to the swap of the first frame showing it (ViewLatency).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <impasto/input/stroke_import.hpp>
#include <impasto/paintcore/step_quality.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "command.hpp"
#include "impasto/bench/simulation.hpp"
#include "impasto/session/recovery_folder.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/session/session_registry.hpp"
#include "latency_lines.hpp"
#include "screen_spot.hpp"
#include "vocabulary.hpp"
#include "window/light_disc_look.hpp"

extern char** environ;

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_window_cmd {
namespace {

struct BenchWindowArgs {
  std::vector<std::string> canvases = {"1024x768", "4096x3072"};
  int window_w = 1400, window_h = 900;
  int brush_cells = 128;  // the brush's width in cells
  std::string head = "round";
  bool wet = false;  // a layer of wet paint under the circles first
  std::string quality{
      util::name_of(paintcore::kStepQualityNames, paintcore::StepQuality::balanced)};
  bool catch_up = true;  // fast steps while the simulation is behind (the window's default)
  bool marks = false;    // compare the recorded session's marks with exact steps'
  double dpi = 300.0;
  double load_mm3 = 0.0;  // paint on the brush (0: the drawing path and an empty brush's sim)
  int circles = 3;
  int moves = 120;  // mouse moves a circle, 8 ms apart (a 125 Hz mouse)
  double radius_px = 150.0;
  int zoom_clicks = 0;  // > 0: wheel clicks instead of circles, in and out by turns
  double zoom_interval_s = 2.0;
  int rotate_drags = 0;  // > 0: right-button drags turning the view, instead of circles
  int light_drags = 0;   // > 0: drags of the light's disc, instead of circles
  bool json = false;

  // What is measured: "input" (pen samples of the circles), or the view motion's kind as the
  // window names it in its report.
  std::string kind() const {
    if (zoom_clicks > 0) return "zoom";
    if (rotate_drags > 0) return "rotation";
    if (light_drags > 0) return "light";
    return "input";
  }
  bool view_motion() const { return kind() != "input"; }
};

struct Latency {
  int width = 0, height = 0;
  LatencyFigures figures;
  MotionFrames frames;                           // view motions only
  std::optional<bench::HeightDifference> marks;  // --marks: the session's against exact steps
};

// The session the window recorded, replayed as recorded (every change of quality where the
// window made it) and at exact quality: how far the window's marks lie from exact steps'.
bench::HeightDifference marks_against_exact(const std::filesystem::path& session) {
  const input::StrokeFile file = input::load_strokes_any(session);
  session::ReplayOptions as_recorded;
  session::ReplayOptions exact;
  exact.quality = paintcore::StepQuality::exact;
  const paintcore::Painting painted = session::replay(file, as_recorded);
  const paintcore::Painting reference = session::replay(file, exact);
  return bench::compare_wet_heights(painted.canvas(), reference.canvas());
}

constexpr double kPi = 3.14159265358979323846;

std::string run_output(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run: " + command);
  std::string out;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
  return out;
}

// `impasto paint` (this executable) with its stdout in `out`.
pid_t start_window(const std::vector<std::string>& args, const std::filesystem::path& out) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start impasto paint");
  return pid;
}

// The dot on the Light panel's disc that marks the light, in window pixels. The panels run
// past the window's height: they are scrolled down, a few wheel clicks at a time, until a
// screenshot shows it.
ScreenSpot find_light_dot(const std::string& window, int window_w, int window_h,
                          const std::filesystem::path& dir) {
  const auto png = dir / "light-disc.png";
  const std::string over_panels = "xdotool mousemove --window " + window + " " +
                                  std::to_string(window_w - 160) + " " +
                                  std::to_string(window_h / 2) + " > /dev/null";
  const int dot_px = static_cast<int>(window::kLightDotRadius);
  for (int scrolls = 0; scrolls <= 12; ++scrolls) {
    // (Bounded: import waits for a window that has gone, holding the display.)
    if (std::system(
            ("timeout 20 import -window " + window + " png:'" + png.string() + "'").c_str()) != 0) {
      throw std::runtime_error("could not take a screenshot of window " + window +
                               " with ImageMagick's import (installed? did the window close?)");
    }
    const render::Image screen = render::read_png(png);
    // Left of the panels nothing is looked at: the canvas may hold that colour.
    if (const auto dot = find_colour_spot(screen, window::kLightDotColour, window_w - 400,
                                          dot_px * dot_px / 2, 4 * dot_px)) {
      return *dot;
    }
    if (std::system((over_panels + " && xdotool click --repeat 3 --delay 30 5").c_str()) != 0) {
      throw std::runtime_error("xdotool could not scroll the panels of window " + window);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  throw std::runtime_error("found no light disc in the panels of window " + window +
                           " (is the Light panel open?)");
}

// The window, told to go (SIGTERM) with the bench's strokes unsaved, kept its session for
// recovery as it would a painter's; a measurement is nothing to recover, and the next
// `impasto paint` would offer it.
void forget_sessions_of(pid_t pid) {
  for (const session::SessionEntry& session :
       session::unfinished_sessions(session::recovery_folder())) {
    if (session.pid == pid) discard_session(session);
  }
}

// A layer of wet paint (White, heavy, about 0.3 mm) under where the circles go:
// horizontal sweeps of a wide flat over the middle of the canvas, which the window fits
// left of its panels as the circles' radius in cells needs.
void write_wet_layer(std::ostream& file, const BenchWindowArgs& args, int width, int height) {
  const double cell_mm = 25.4 / args.dpi;
  const double pixels_per_cell = std::min(static_cast<double>(args.window_w - 360) / width,
                                          static_cast<double>(args.window_h - 60) / height);
  const double reach = args.radius_px / pixels_per_cell + args.brush_cells;  // cells
  const double sweep = std::clamp(reach / 2.0, 16.0, 600.0);                 // the flat's width
  const double cx = width / 2.0, cy = height / 2.0;
  const double x0 = std::max(0.0, cx - reach), x1 = std::min(width - 1.0, cx + reach);
  file << "brush flat size=" << sweep * cell_mm << " stiffness=0.5\n";
  double t = 0.0;
  for (double y = std::max(sweep / 2, cy - reach); y <= std::min(height - sweep / 2, cy + reach);
       y += 0.8 * sweep) {
    const double length_mm = (x1 - x0) * cell_mm;
    file << "wipe\nload " << 1.3 * 0.3 * length_mm * sweep * cell_mm << " \"White\" 1 body=heavy\n";
    for (double x = x0; x <= x1; x += sweep / 8.0, t += 0.008)
      file << "pen " << t << " " << x * cell_mm << " " << y * cell_mm << " 0.7 0 0 0 17\n";
    file << "pen " << t << " " << x1 * cell_mm << " " << y * cell_mm << " 0 0 0 0 16\n";
    t += 0.5;
  }
}

// Until the window says its replay is on screen (cmd_paint's "replayed:" line).
void wait_for_replay(const std::filesystem::path& out, double timeout_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    std::ifstream text(out);
    const std::string printed((std::istreambuf_iterator<char>(text)), {});
    if (printed.find("replayed: ") != std::string::npos) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  throw std::runtime_error("the window did not show its replay within " +
                           std::to_string(static_cast<int>(timeout_s)) + " s");
}

Latency measure(const BenchWindowArgs& args, int width, int height,
                const std::filesystem::path& dir) {
  const double cell_mm = 25.4 / args.dpi;
  const std::string name = std::to_string(width) + "x" + std::to_string(height);
  const auto strokes = dir / (name + ".strokes");
  {
    std::ofstream file(strokes);
    file << "impasto-strokes 1\ncanvas " << width << " " << height << " " << args.dpi << "\n";
    if (args.wet) write_wet_layer(file, args, width, height);
    file << "brush " << args.head << " size=" << args.brush_cells * cell_mm << " stiffness=0.5\n";
    if (args.load_mm3 > 0) file << "wipe\nload " << args.load_mm3 << " \"Red Oxide\" 5\n";
  }
  const auto out = dir / (name + "-window.txt");
  const auto session = dir / (name + "-session.strokes");
  std::vector<std::string> paint = {"impasto",         "paint",
                                    "--replay",        strokes.string(),
                                    "--record",        session.string(),
                                    "--window-width",  std::to_string(args.window_w),
                                    "--window-height", std::to_string(args.window_h),
                                    "--quality",       args.quality};
  if (!args.catch_up) paint.push_back("--no-catch-up");
  const pid_t pid = start_window(paint, out);
  std::string failure;
  try {
    const std::string id = run_output("timeout 30 xdotool search --sync --onlyvisible --pid " +
                                      std::to_string(pid) + " --name ' Impasto$' | head -1");
    if (id.empty()) throw std::runtime_error("the window did not appear within 30 s");
    const std::string window = id.substr(0, id.find('\n'));
    wait_for_replay(out, args.wet ? 600.0 : 60.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    // Circles about the middle of the canvas's part of the window (left of the panels).
    const double cx = (args.window_w - 360) / 2.0, cy = args.window_h / 2.0;
    const auto xdotool = [&](const std::string& script, const std::string& what) {
      if (std::system(("xdotool " + script + " > /dev/null").c_str()) != 0) {
        throw std::runtime_error("xdotool could not " + what + " in window " + window +
                                 " (did it close?)");
      }
    };
    const auto at = [&](double x, double y, bool sync = false) {
      return "mousemove --window " + window + (sync ? " --sync " : " ") +
             std::to_string(std::lround(x)) + " " + std::to_string(std::lround(y));
    };
    // Held down at `path(0)`, moved to path(k / moves) every 8 ms (a 125 Hz mouse), let go.
    const auto drag = [&](int button, const auto& path, const std::string& what) {
      const auto [x0, y0] = path(0.0);
      std::string script = at(x0, y0, true) + " mousedown " + std::to_string(button);
      for (int k = 1; k <= args.moves; ++k) {
        const auto [x, y] = path(static_cast<double>(k) / args.moves);
        script += " sleep 0.008 " + at(x, y);
      }
      xdotool(script + " mouseup " + std::to_string(button), what);
    };
    if (args.zoom_clicks > 0) {
      // Wheel clicks at the middle of the canvas (X buttons 4 and 5: in, out), each after
      // the view has been still for the interval.
      std::ostringstream cmd;
      cmd << at(cx, cy, true);
      for (int k = 0; k < args.zoom_clicks; ++k) {
        cmd << " sleep " << args.zoom_interval_s << " click " << (k % 2 == 0 ? 4 : 5);
      }
      cmd << " sleep " << args.zoom_interval_s;
      xdotool(cmd.str(), "click");
    }
    for (int d = 0; d < args.rotate_drags; ++d) {
      // The right button turns the view about the window's centre by the angle the pointer
      // turns about it: a whole turn on a circle about the centre, clear of the panels.
      const double ox = args.window_w / 2.0, oy = args.window_h / 2.0;
      const double r =
          std::max(20.0, std::min({200.0, 0.3 * args.window_h, args.window_w - 360 - ox - 10.0}));
      drag(
          3,
          [&](double t) {
            return std::pair{ox + r * std::cos(2 * kPi * t), oy + r * std::sin(2 * kPi * t)};
          },
          "drag with the right button");
      std::this_thread::sleep_for(std::chrono::seconds(1));  // refined, as between two turns
    }
    if (args.light_drags > 0) {
      const ScreenSpot dot = find_light_dot(window, args.window_w, args.window_h, dir);
      for (int d = 0; d < args.light_drags; ++d) {
        // From the dot round a circle of 20 px beside it and back: the light swings about.
        drag(
            1,
            [&](double t) {
              return std::pair{dot.x + 20.0 * (std::cos(2 * kPi * t) - 1.0),
                               dot.y + 20.0 * std::sin(2 * kPi * t)};
            },
            "drag the light's disc");
        std::this_thread::sleep_for(std::chrono::seconds(1));
      }
    }
    for (int c = 0; c < (args.view_motion() ? 0 : args.circles); ++c) {
      drag(
          1,
          [&](double t) {
            return std::pair{cx + args.radius_px * std::cos(2 * kPi * t),
                             cy + args.radius_px * std::sin(2 * kPi * t)};
          },
          "move the mouse");
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  } catch (const std::exception& e) {
    failure = e.what();
  }
  kill(pid, SIGTERM);  // the window closes cleanly and prints its figures
  int status = 0;
  waitpid(pid, &status, 0);
  forget_sessions_of(pid);
  if (!failure.empty()) throw std::runtime_error(failure);
  std::ifstream text(out);
  const std::string printed((std::istreambuf_iterator<char>(text)), {});
  const std::optional<LatencyFigures> figures = find_latency_line(printed, args.kind());
  const std::optional<MotionFrames> frames = find_motion_frames_line(printed);
  if (!figures || (args.view_motion() && !frames)) {
    throw std::runtime_error("impasto paint printed no " + args.kind() + " latency (exit status " +
                             std::to_string(status) + "): " + printed);
  }
  Latency result{width, height, *figures, frames.value_or(MotionFrames{}), std::nullopt};
  if (args.marks) result.marks = marks_against_exact(session);
  return result;
}

void run(const BenchWindowArgs& args) {
  if (!std::getenv("DISPLAY")) {
    throw std::runtime_error("bench window needs an X display: set DISPLAY (e.g. Xvfb :99 &)");
  }
  if (std::system("command -v xdotool > /dev/null") != 0) {
    throw std::runtime_error("bench window sends its mouse events with xdotool: install it");
  }
  if (args.light_drags > 0 && std::system("command -v import > /dev/null") != 0) {
    throw std::runtime_error(
        "bench window --light-drag finds the light's disc in a screenshot taken with "
        "ImageMagick's import: install it");
  }
  const auto dir =
      std::filesystem::temp_directory_path() / ("impasto-bench-window-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::vector<Latency> results;
  for (const std::string& canvas : args.canvases) {
    const CanvasSize size = parse_canvas_size(canvas, "--canvas");
    results.push_back(measure(args, size.width, size.height, dir));
  }
  std::filesystem::remove_all(dir);
  if (args.json) {
    nlohmann::json j;
    j["window"] = {args.window_w, args.window_h};
    j["kind"] = args.kind();
    j["brush_cells"] = args.brush_cells;
    j["head"] = args.head;
    j["wet"] = args.wet;
    j["load_mm3"] = args.load_mm3;
    if (args.zoom_clicks > 0) j["zoom_interval_s"] = args.zoom_interval_s;
    if (args.rotate_drags > 0 || args.light_drags > 0) j["moves_per_drag"] = args.moves;
    for (const Latency& r : results) {
      j["canvases"].push_back({{"width", r.width},
                               {"height", r.height},
                               {"median_ms", r.figures.median_ms},
                               {"p95_ms", r.figures.p95_ms},
                               {"samples", r.figures.events}});
      if (r.marks) {
        j["canvases"].back()["marks_against_exact"] = {
            {"mean_height_mm", r.marks->mean_height_mm},
            {"mean_error_mm", r.marks->mean_error_mm},
            {"max_error_mm", r.marks->max_error_mm},
            {"mean_block_error_mm", r.marks->mean_block_error_mm},
            {"max_block_error_mm", r.marks->max_block_error_mm}};
      }
      if (args.view_motion()) {
        j["canvases"].back()["coarse_frames"] = r.frames.coarse;
        j["canvases"].back()["coarse_factor"] = r.frames.median_factor;
        j["canvases"].back()["frame_interval_ms"] = r.frames.interval_ms;
      }
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::ostringstream what;
  std::string events = "samples";
  if (args.zoom_clicks > 0) {
    what << "zoom latency, wheel click to the swap showing it (" << args.zoom_clicks << " clicks "
         << args.zoom_interval_s << " s apart";
    events = "clicks";
  } else if (args.rotate_drags > 0) {
    what << "rotation latency, pointer move to the swap showing it (" << args.rotate_drags
         << " right-button turns of " << args.moves << " moves at 125 Hz";
    events = "moves";
  } else if (args.light_drags > 0) {
    what << "light latency, pointer event to the swap showing it (" << args.light_drags
         << " drags of the light's disc, " << args.moves << " moves at 125 Hz";
    events = "events";
  } else {
    what << "input latency, mouse event to the swap showing it (" << args.brush_cells << "-cell "
         << args.head << ", " << args.load_mm3 << " mm3 loaded"
         << (args.wet ? " over wet paint" : "") << ", " << args.circles << " circles of "
         << args.moves << " moves at 125 Hz, quality " << args.quality
         << (args.catch_up ? " (fast while behind)" : "");
  }
  std::cout << what.str() << ", " << args.window_w << "x" << args.window_h << " window):\n";
  for (const Latency& r : results) {
    std::cout << "  " << r.width << "x" << r.height << " canvas: median " << r.figures.median_ms
              << " ms, 95th percentile " << r.figures.p95_ms << " ms over " << r.figures.events
              << " " << events;
    if (args.view_motion()) {
      std::cout << "; " << r.frames.coarse << " coarse frames, median factor "
                << r.frames.median_factor << ", frames " << r.frames.interval_ms
                << " ms apart while moving";
    }
    if (r.marks) {
      std::cout << "; wet paint against exact steps: " << r.marks->mean_error_mm << " mm mean, "
                << r.marks->max_error_mm << " mm max (4x4 blocks " << r.marks->mean_block_error_mm
                << " / " << r.marks->max_block_error_mm << " mm; mean height "
                << r.marks->mean_height_mm << " mm)";
    }
    std::cout << "\n";
  }
}

void setup(CLI::App& root) {
  auto args = std::make_shared<BenchWindowArgs>();
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "window",
      "Input latency of the painting window: scripted mouse circles, wheel clicks or drags "
      "(xdotool)");
  cmd->add_option("--canvas", args->canvases, "Canvas sizes in cells, WIDTHxHEIGHT")
      ->capture_default_str();
  cmd->add_option("--window-width", args->window_w, "Window width")->check(finite_range(320, 8192));
  cmd->add_option("--window-height", args->window_h, "Window height")
      ->check(finite_range(240, 8192));
  cmd->add_option("--brush", args->brush_cells, "Brush width in cells")
      ->check(finite_range(1, 4096));
  cmd->add_option("--head", args->head, "Brush head (a file in the brushes folder)")
      ->capture_default_str();
  add_quality_option(*cmd, args->quality, "the window's")->capture_default_str();
  cmd->add_flag("--no-catch-up{false}", args->catch_up,
                "The window keeps its quality while behind (by default it takes fast steps)");
  cmd->add_flag("--marks", args->marks,
                "Then replay the session the window recorded, as recorded and at exact quality, "
                "and compare their wet paint (the cost of its quality in the marks)");
  cmd->add_flag("--wet", args->wet,
                "Paint a layer of wet paint (White, heavy, about 0.3 mm) under the "
                "circles first");
  add_dpi_option(*cmd, args->dpi);
  cmd->add_option("--load", args->load_mm3, "Paint loaded on the brush, mm3 (Red Oxide)")
      ->check(finite_range(0.0, 10000.0));
  cmd->add_option("--circles", args->circles, "Circles drawn")->check(finite_range(1, 100));
  cmd->add_option("--moves", args->moves, "Mouse moves a circle or a drag, 8 ms apart")
      ->check(finite_range(8, 10000));
  CLI::Option* zoom =
      cmd->add_option("--zoom", args->zoom_clicks,
                      "Wheel clicks instead of circles (in and out by turns): the latency of a "
                      "zoom step's first frame")
          ->check(finite_range(1, 1000));
  cmd->add_option("--zoom-interval", args->zoom_interval_s, "Seconds between wheel clicks")
      ->check(finite_range(0.0, 60.0))
      ->capture_default_str();
  CLI::Option* rotate =
      cmd->add_option("--rotate", args->rotate_drags,
                      "Right-button drags instead of circles, each a whole turn of the view "
                      "(--moves moves), a second apart: the latency of a rotation's frames")
          ->check(finite_range(1, 1000))
          ->excludes(zoom);
  cmd->add_option("--light-drag", args->light_drags,
                  "Drags of the Light panel's disc instead of circles (--moves moves each, a "
                  "second apart; found in a screenshot, ImageMagick's import): the latency of "
                  "a light change's frames")
      ->check(finite_range(1, 1000))
      ->excludes(zoom)
      ->excludes(rotate);
  add_json_flag(*cmd, args->json, "the latencies of each canvas");
  cmd->callback([args] { run(*args); });
}

const CommandRegistrar registrar("bench window", setup);

}  // namespace
}  // namespace impasto::app::bench_window_cmd
