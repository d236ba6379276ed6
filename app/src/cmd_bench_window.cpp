// impasto bench window: what a user waits for in the painting window — the time from each
// mouse event's own timestamp to the buffer swap that shows it — measured with real X events
// (xdotool) sent to `impasto paint` on the current DISPLAY (Xvfb with llvmpipe, or a desktop).
// The window keeps the figures (InputLatency) and prints them when SIGTERM closes it. With
// --zoom, wheel clicks instead: from each click's own time to the swap of the first frame
// showing its zoom step.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

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
#include <vector>

#include "command.hpp"
#include "vocabulary.hpp"

extern char** environ;

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_window_cmd {
namespace {

struct BenchWindowArgs {
  std::vector<std::string> canvases = {"1024x768", "4096x3072"};
  int window_w = 1400, window_h = 900;
  int brush_cells = 128;  // the brush's width in cells
  double dpi = 300.0;
  double load_mm3 = 0.0;  // paint on the brush (0: the drawing path and an empty brush's sim)
  int circles = 3;
  int moves = 120;  // mouse moves a circle, 8 ms apart (a 125 Hz mouse)
  double radius_px = 150.0;
  int zoom_clicks = 0;  // > 0: wheel clicks instead of circles, in and out by turns
  double zoom_interval_s = 2.0;
  bool json = false;
};

struct Latency {
  int width = 0, height = 0;
  double median_ms = 0, p95_ms = 0;
  int samples = 0;
  int coarse_frames = 0, coarse_factor = 0;  // under --zoom
};

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

Latency measure(const BenchWindowArgs& args, int width, int height,
                const std::filesystem::path& dir) {
  const double cell_mm = 25.4 / args.dpi;
  const std::string name = std::to_string(width) + "x" + std::to_string(height);
  const auto strokes = dir / (name + ".strokes");
  {
    std::ofstream file(strokes);
    file << "impasto-strokes 1\ncanvas " << width << " " << height << " " << args.dpi
         << "\nbrush round size=" << args.brush_cells * cell_mm << " stiffness=0.5\n";
    if (args.load_mm3 > 0) file << "load " << args.load_mm3 << " \"Burnt Sienna\" 5\n";
  }
  const auto out = dir / (name + "-window.txt");
  const pid_t pid = start_window(
      {"impasto", "paint", "--replay", strokes.string(), "--record",
       (dir / (name + "-session.strokes")).string(), "--window-width",
       std::to_string(args.window_w), "--window-height", std::to_string(args.window_h)},
      out);
  std::optional<Latency> result;
  std::string failure;
  try {
    const std::string id = run_output("timeout 30 xdotool search --sync --onlyvisible --pid " +
                                      std::to_string(pid) + " --name ' Impasto$' | head -1");
    if (id.empty()) throw std::runtime_error("the window did not appear within 30 s");
    const std::string window = id.substr(0, id.find('\n'));
    std::this_thread::sleep_for(std::chrono::seconds(3));  // the replay applied, panels laid out
    // Circles about the middle of the canvas's part of the window (left of the panels).
    const double cx = (args.window_w - 360) / 2.0, cy = args.window_h / 2.0;
    if (args.zoom_clicks > 0) {
      // Wheel clicks at the middle of the canvas (X buttons 4 and 5: in, out), each after
      // the view has been still for the interval.
      std::ostringstream cmd;
      cmd << "xdotool mousemove --window " << window << " --sync " << std::lround(cx) << " "
          << std::lround(cy);
      for (int k = 0; k < args.zoom_clicks; ++k) {
        cmd << " sleep " << args.zoom_interval_s << " click " << (k % 2 == 0 ? 4 : 5);
      }
      cmd << " sleep " << args.zoom_interval_s << " > /dev/null";
      if (std::system(cmd.str().c_str()) != 0) {
        throw std::runtime_error("xdotool could not click in window " + window +
                                 " (did it close?)");
      }
    }
    for (int c = 0; c < (args.zoom_clicks > 0 ? 0 : args.circles); ++c) {
      std::ostringstream cmd;
      cmd << "xdotool mousemove --window " << window << " --sync "
          << std::lround(cx + args.radius_px) << " " << std::lround(cy) << " mousedown 1";
      for (int k = 1; k <= args.moves; ++k) {
        const double a = 2.0 * 3.14159265358979323846 * k / args.moves;
        cmd << " sleep 0.008 mousemove --window " << window << " "
            << std::lround(cx + args.radius_px * std::cos(a)) << " "
            << std::lround(cy + args.radius_px * std::sin(a));
      }
      cmd << " mouseup 1 > /dev/null";
      if (std::system(cmd.str().c_str()) != 0) {
        throw std::runtime_error("xdotool could not move the mouse in window " + window +
                                 " (did it close?)");
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  } catch (const std::exception& e) {
    failure = e.what();
  }
  kill(pid, SIGTERM);  // the window closes cleanly and prints its figures
  int status = 0;
  waitpid(pid, &status, 0);
  if (!failure.empty()) throw std::runtime_error(failure);
  std::ifstream text(out);
  const std::string printed((std::istreambuf_iterator<char>(text)), {});
  // "... median M ms, 95th percentile P ms over N samples; ..." (no std::regex: GCC 12's
  // regex trips -Wmaybe-uninitialized in the sanitizer build).
  double median = 0, p95 = 0;
  int samples = 0, coarse_frames = 0, coarse_factor = 0;
  if (args.zoom_clicks > 0) {
    // "zoom latency (...): median M ms, 95th percentile P ms over N clicks; C coarse frames,
    // median factor F"
    const std::size_t line = printed.find("zoom latency");
    const std::size_t at = printed.find("median ", line);
    if (line == std::string::npos || at == std::string::npos ||
        std::sscanf(printed.c_str() + at,
                    "median %lf ms, 95th percentile %lf ms over %d clicks; %d coarse frames, "
                    "median factor %d",
                    &median, &p95, &samples, &coarse_frames, &coarse_factor) != 5) {
      throw std::runtime_error("impasto paint printed no zoom latency (exit status " +
                               std::to_string(status) + "): " + printed);
    }
    return {width, height, median, p95, samples, coarse_frames, coarse_factor};
  }
  const std::size_t at = printed.find("median ", printed.find("input latency"));
  if (at == std::string::npos ||
      std::sscanf(printed.c_str() + at, "median %lf ms, 95th percentile %lf ms over %d samples",
                  &median, &p95, &samples) != 3) {
    throw std::runtime_error("impasto paint printed no input latency (exit status " +
                             std::to_string(status) + "): " + printed);
  }
  return {width, height, median, p95, samples};
}

void run(const BenchWindowArgs& args) {
  if (!std::getenv("DISPLAY")) {
    throw std::runtime_error("bench window needs an X display: set DISPLAY (e.g. Xvfb :99 &)");
  }
  if (std::system("command -v xdotool > /dev/null") != 0) {
    throw std::runtime_error("bench window sends its mouse events with xdotool: install it");
  }
  const auto dir =
      std::filesystem::temp_directory_path() / ("impasto-bench-window-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::vector<Latency> results;
  for (const std::string& canvas : args.canvases) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(canvas);
    if (!(in >> w >> x >> h) || x != 'x' || w < 1 || h < 1) {
      throw std::runtime_error("--canvas wants WIDTHxHEIGHT in cells, not '" + canvas + "'");
    }
    results.push_back(measure(args, w, h, dir));
  }
  std::filesystem::remove_all(dir);
  if (args.json) {
    nlohmann::json j;
    j["window"] = {args.window_w, args.window_h};
    j["brush_cells"] = args.brush_cells;
    j["load_mm3"] = args.load_mm3;
    if (args.zoom_clicks > 0) j["zoom_interval_s"] = args.zoom_interval_s;
    for (const Latency& r : results) {
      j["canvases"].push_back({{"width", r.width},
                               {"height", r.height},
                               {"median_ms", r.median_ms},
                               {"p95_ms", r.p95_ms},
                               {"samples", r.samples}});
      if (args.zoom_clicks > 0) {
        j["canvases"].back()["coarse_frames"] = r.coarse_frames;
        j["canvases"].back()["coarse_factor"] = r.coarse_factor;
      }
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  if (args.zoom_clicks > 0) {
    std::cout << "zoom latency, wheel click to the swap showing it (" << args.window_w << "x"
              << args.window_h << " window, " << args.zoom_clicks << " clicks "
              << args.zoom_interval_s << " s apart):\n";
    for (const Latency& r : results) {
      std::cout << "  " << r.width << "x" << r.height << " canvas: median " << r.median_ms
                << " ms, 95th percentile " << r.p95_ms << " ms over " << r.samples << " clicks; "
                << r.coarse_frames << " coarse frames, median factor " << r.coarse_factor << "\n";
    }
    return;
  }
  std::cout << "input latency, mouse event to the swap showing it (" << args.window_w << "x"
            << args.window_h << " window, " << args.brush_cells << "-cell brush, " << args.load_mm3
            << " mm3 loaded, " << args.circles << " circles of " << args.moves
            << " moves at 125 Hz):\n";
  for (const Latency& r : results) {
    std::cout << "  " << r.width << "x" << r.height << " canvas: median " << r.median_ms
              << " ms, 95th percentile " << r.p95_ms << " ms over " << r.samples << " samples\n";
  }
}

void setup(CLI::App& root) {
  auto args = std::make_shared<BenchWindowArgs>();
  CLI::App* bench = bench_group(root);
  CLI::App* cmd = bench->add_subcommand(
      "window", "Input latency of the painting window, scripted mouse circles (xdotool)");
  cmd->add_option("--canvas", args->canvases, "Canvas sizes in cells, WIDTHxHEIGHT")
      ->capture_default_str();
  cmd->add_option("--window-width", args->window_w, "Window width")->check(CLI::Range(320, 8192));
  cmd->add_option("--window-height", args->window_h, "Window height")->check(CLI::Range(240, 8192));
  cmd->add_option("--brush", args->brush_cells, "Brush width in cells")->check(CLI::Range(1, 4096));
  add_dpi_option(*cmd, args->dpi);
  cmd->add_option("--load", args->load_mm3, "Paint loaded on the brush, mm3 (Burnt Sienna)")
      ->check(CLI::Range(0.0, 10000.0));
  cmd->add_option("--circles", args->circles, "Circles drawn")->check(CLI::Range(1, 100));
  cmd->add_option("--moves", args->moves, "Mouse moves a circle")->check(CLI::Range(8, 10000));
  cmd->add_option("--zoom", args->zoom_clicks,
                  "Wheel clicks instead of circles (in and out by turns): the latency of a "
                  "zoom step's first frame")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--zoom-interval", args->zoom_interval_s, "Seconds between wheel clicks")
      ->check(CLI::Range(0.0, 60.0))
      ->capture_default_str();
  add_json_flag(*cmd, args->json, "the latencies of each canvas");
  cmd->callback([args] { run(*args); });
}

const CommandRegistrar registrar("bench window", setup);

}  // namespace
}  // namespace impasto::app::bench_window_cmd
