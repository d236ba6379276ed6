#include "latency_lines.hpp"

#include <cstdio>
#include <sstream>

namespace impasto::app {
namespace {

// Where a line starting with `head` begins in `printed`, or npos.
std::size_t line_starting(std::string_view printed, std::string_view head) {
  for (std::size_t at = printed.find(head); at != std::string_view::npos;
       at = printed.find(head, at + 1)) {
    if (at == 0 || printed[at - 1] == '\n') return at;
  }
  return std::string_view::npos;
}

// The rest of the line from `at` (sscanf wants a terminated string; no std::regex: GCC 12's
// trips -Wmaybe-uninitialized in the sanitizer build).
std::string rest_of_line(std::string_view printed, std::size_t at) {
  const std::size_t end = printed.find('\n', at);
  return std::string(printed.substr(at, end == std::string_view::npos ? end : end - at));
}

}  // namespace

std::string latency_line(std::string_view kind, std::string_view event, std::string_view events,
                         const LatencyFigures& figures) {
  std::ostringstream line;
  line << kind << " latency (" << event << " to the swap showing it): median " << figures.median_ms
       << " ms, 95th percentile " << figures.p95_ms << " ms over " << figures.events << " "
       << events;
  return line.str();
}

std::optional<LatencyFigures> find_latency_line(std::string_view printed, std::string_view kind) {
  const std::size_t at = line_starting(printed, std::string(kind) + " latency (");
  if (at == std::string_view::npos) return std::nullopt;
  const std::string line = rest_of_line(printed, at);
  const std::size_t figures_at = line.find("): median ");
  LatencyFigures f;
  if (figures_at == std::string::npos ||
      std::sscanf(line.c_str() + figures_at, "): median %lf ms, 95th percentile %lf ms over %d",
                  &f.median_ms, &f.p95_ms, &f.events) != 3) {
    return std::nullopt;
  }
  return f;
}

std::string motion_frames_line(const MotionFrames& frames) {
  std::ostringstream line;
  line << "view motion: " << frames.coarse << " coarse frames, median factor "
       << frames.median_factor << "; frames " << frames.interval_ms
       << " ms apart while moving (median)";
  return line.str();
}

std::optional<MotionFrames> find_motion_frames_line(std::string_view printed) {
  const std::size_t at = line_starting(printed, "view motion: ");
  if (at == std::string_view::npos) return std::nullopt;
  MotionFrames f;
  if (std::sscanf(rest_of_line(printed, at).c_str(),
                  "view motion: %d coarse frames, median factor %d; frames %lf ms apart", &f.coarse,
                  &f.median_factor, &f.interval_ms) != 3) {
    return std::nullopt;
  }
  return f;
}

}  // namespace impasto::app
