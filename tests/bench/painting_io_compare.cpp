// Times Painting::load or Painting::save of one painting, with whichever paintcore it is
// linked against, so that two builds (the commit before a change and after) are compared on
// one machine by painting_io_compare.sh. Only the public API, so it builds against older trees.
// Prints one JSON line: wall ms and the peak resident memory the operation added.
#include <malloc.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <impasto/paintcore/painting.hpp>
#include <string>

namespace {

double status_kb(const char* field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(std::string(field).size()));
  return -1;
}

// The kernel's high-water mark reset (clear_refs 5), freed memory handed back first.
struct PeakMemory {
  double before_kb;
  PeakMemory() {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    before_kb = status_kb("VmRSS:");
  }
  double extra_mb() const { return (status_kb("VmHWM:") - before_kb) / 1024.0; }
};

// CPU time of the whole process (every thread): less at the mercy of other programs than the
// wall time on a busy machine.
double cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  using impasto::paintcore::Painting;
  if (argc != 4 || (std::string(argv[1]) != "load" && std::string(argv[1]) != "save")) {
    std::fprintf(stderr, "usage: %s load|save PAINTING OUT.impasto\n", argv[0]);
    return 2;
  }
  if (std::string(argv[1]) == "load") {
    const PeakMemory peak;
    const double cpu_start = cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    const Painting painting = Painting::load(argv[2]);
    const double ms = ms_since(start);
    std::printf(
        "{\"op\":\"load\",\"ms\":%.1f,\"cpu_ms\":%.1f,\"peak_extra_mb\":%.1f,\"painting_mb\":%.1f}"
        "\n",
        ms, cpu_ms() - cpu_start, peak.extra_mb(),
        static_cast<double>(painting.memory_bytes()) / (1 << 20));
  } else {
    const Painting painting = Painting::load(argv[2]);
    const PeakMemory peak;
    const double cpu_start = cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    painting.save(argv[3]);
    const double ms = ms_since(start);
    std::printf("{\"op\":\"save\",\"ms\":%.1f,\"cpu_ms\":%.1f,\"peak_extra_mb\":%.1f}\n", ms,
                cpu_ms() - cpu_start, peak.extra_mb());
  }
}
