// impasto bench io: what saving and loading a big painting costs. A painting (a file, or a
// synthetic one: --size cells with --painted percent of its tiles holding wet paint of four
// pigments over a dry layer, about 250 MB by default) is saved and loaded --runs times:
// wall times and MB/s (medians), and the memory each took at its peak beyond what the
// process held before, against the memory of the painting itself.
#include <malloc.h>

#include <impasto/paintcore/painting.hpp>
#include <impasto/paintcore/synthetic_painting.hpp>

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "command.hpp"
#include "impasto/session/replay.hpp"
#include "impasto/util/statistics.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::bench_io_cmd {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A field of /proc/self/status in kB ("VmRSS", "VmHWM"), or -1 where there is none.
double status_kb(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1));
  return -1.0;
}

// Peak resident memory of a piece of work beyond what the process held before it: the
// kernel's high-water mark is reset first (Linux 4.0: clear_refs 5), and freed memory handed
// back, so that an earlier peak or the allocator's free lists do not count.
class PeakMemory {
 public:
  PeakMemory() {
    malloc_trim(0);
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    reset_ = static_cast<bool>(clear);
    before_kb_ = status_kb("VmRSS");
  }
  // MB above the start; nullopt where the peak could not be reset (it would be the process's).
  std::optional<double> extra_mb() const {
    if (!reset_ || before_kb_ < 0) return std::nullopt;
    return (status_kb("VmHWM") - before_kb_) / 1024.0;
  }

 private:
  bool reset_ = false;
  double before_kb_ = -1.0;
};

struct BenchIoArgs {
  std::string painting;  // empty: synthetic
  std::optional<CanvasSize> size;
  double painted_percent = 3.0;
  int runs = 3;
  int threads = 0;
  std::string dir;   // where the file is saved (default: the system's temp folder)
  std::string save;  // keep the painting here (for measuring other commands on it)
  bool json = false;
};

struct Sample {
  double ms = 0;
  std::optional<double> extra_mb;
};

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::optional<double> median_of(const std::vector<Sample>& samples) {
  std::vector<double> values;
  for (const Sample& s : samples)
    if (s.extra_mb) values.push_back(*s.extra_mb);
  if (values.empty()) return std::nullopt;
  return util::median(values);
}

std::vector<double> times_of(const std::vector<Sample>& samples) {
  std::vector<double> ms;
  for (const Sample& s : samples) ms.push_back(s.ms);
  return ms;
}

void print_table(const paintcore::Painting& painting, double painting_mb, double file_mb,
                 double save_ms, double load_ms, const std::optional<double>& save_extra,
                 const std::optional<double>& load_extra, int runs);

void run(const BenchIoArgs& args) {
  const auto build_start = Clock::now();
  std::optional<paintcore::Painting> painting;
  if (!args.painting.empty()) {
    painting.emplace(paintcore::Painting::load(args.painting, args.threads));
  } else {
    paintcore::SyntheticPaintingSpec spec;
    if (args.size) {
      spec.width_cells = args.size->width;
      spec.height_cells = args.size->height;
    }
    spec.painted_share = args.painted_percent / 100.0;
    const auto& palette = session::demo_palette();
    spec.slots.assign(palette.begin(), palette.begin() + 4);
    painting.emplace(paintcore::synthetic_painting(spec, args.threads));
  }
  const double build_ms = ms_since(build_start);
  const paintcore::Canvas& canvas = painting->canvas();
  const auto painted = static_cast<int>(canvas.allocated_tiles());
  const double painting_mb = static_cast<double>(painting->memory_bytes()) / (1 << 20);
  const std::uint64_t hash = painting->state_hash();

  const std::filesystem::path dir =
      args.dir.empty() ? std::filesystem::temp_directory_path() : std::filesystem::path(args.dir);
  const std::filesystem::path file =
      dir / ("impasto-bench-io-" + std::to_string(::getpid()) + ".impasto");
  struct Remove {
    std::filesystem::path path;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } remove{file};

  std::vector<Sample> saves, loads;
  std::uintmax_t file_bytes = 0;
  for (int run = 0; run < args.runs; ++run) {
    {
      const PeakMemory peak;
      const auto start = Clock::now();
      painting->save(file);
      saves.push_back({ms_since(start), peak.extra_mb()});
    }
    file_bytes = std::filesystem::file_size(file);
    {
      const PeakMemory peak;
      const auto start = Clock::now();
      const paintcore::Painting loaded = paintcore::Painting::load(file, args.threads);
      loads.push_back({ms_since(start), peak.extra_mb()});
      if (loaded.state_hash() != hash)
        throw std::runtime_error("bench io: the loaded painting differs from the saved one");
    }
  }
  const double file_mb = static_cast<double>(file_bytes) / (1 << 20);
  const double save_ms = util::median(times_of(saves));
  const double load_ms = util::median(times_of(loads));
  const auto save_extra = median_of(saves), load_extra = median_of(loads);
  if (args.json) {
    std::cout << nlohmann::json{{"width", canvas.width_cells()},
                                {"height", canvas.height_cells()},
                                {"painted_tiles", painted},
                                {"tiles", canvas.tile_count()},
                                {"slots", painting->slot_count()},
                                {"file_mb", file_mb},
                                {"painting_mb", painting_mb},
                                {"build_ms", build_ms},
                                {"save_ms", save_ms},
                                {"load_ms", load_ms},
                                {"save_mb_per_s", file_mb / (save_ms / 1e3)},
                                {"load_mb_per_s", file_mb / (load_ms / 1e3)},
                                {"save_peak_extra_mb", optional_json(save_extra)},
                                {"load_peak_extra_mb", optional_json(load_extra)},
                                {"save_runs_ms", times_of(saves)},
                                {"load_runs_ms", times_of(loads)},
                                {"runs", args.runs},
                                {"threads", painting->threads()}}
              << "\n";
  } else {
    print_table(*painting, painting_mb, file_mb, save_ms, load_ms, save_extra, load_extra,
                args.runs);
  }
  if (!args.save.empty()) {
    painting->save(args.save);
    note("wrote " + args.save);
  }
}

void print_table(const paintcore::Painting& painting, double painting_mb, double file_mb,
                 double save_ms, double load_ms, const std::optional<double>& save_extra,
                 const std::optional<double>& load_extra, int runs) {
  const paintcore::Canvas& canvas = painting.canvas();
  const auto painted = static_cast<int>(canvas.allocated_tiles());
  const auto mb = [](const std::optional<double>& v) {
    return v ? std::to_string(static_cast<long long>(*v + 0.5)) + " MB" : std::string("unknown");
  };
  std::printf("%dx%d cells, %d of %d tiles painted, %d slots: %.1f MB in memory, %.1f MB file\n",
              canvas.width_cells(), canvas.height_cells(), painted, canvas.tile_count(),
              painting.slot_count(), painting_mb, file_mb);
  std::printf("save %9.1f ms %8.1f MB/s (median of %d), peak memory beyond the painting %s\n",
              save_ms, file_mb / (save_ms / 1e3), runs, mb(save_extra).c_str());
  std::printf("load %9.1f ms %8.1f MB/s (median of %d), peak memory %s (the painting: %.0f MB)\n",
              load_ms, file_mb / (load_ms / 1e3), runs, mb(load_extra).c_str(), painting_mb);
}

const CommandRegistrar registrar("bench io", [](CLI::App& root) {
  CLI::App* bench = bench_group(root);
  auto args = std::make_shared<BenchIoArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "io", "Painting file save and load: ms, MB/s and peak memory against the painting's");
  cmd->add_option("painting", args->painting,
                  "A .impasto painting (default: a synthetic one of --size)");
  add_size_option(*cmd, args->size, "the synthetic painting's (default 16384x16384)");
  cmd->add_option("--painted", args->painted_percent,
                  "Percent of the synthetic canvas's tiles that hold paint")
      ->check(finite_range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--runs", args->runs, "Saves and loads (the median is reported)")
      ->check(finite_range(1, 100))
      ->capture_default_str();
  cmd->add_option("--dir", args->dir, "Folder the file is saved in (default: the temp folder)");
  add_save_option(*cmd, args->save,
                  "the painting measured (a synthetic one, to time other commands)");
  add_threads_option(*cmd, args->threads);
  add_json_flag(*cmd, args->json,
                "one object: save_ms, load_ms, save_mb_per_s, load_mb_per_s, "
                "save_peak_extra_mb, load_peak_extra_mb, painting_mb, file_mb, ...");
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace impasto::app::bench_io_cmd
