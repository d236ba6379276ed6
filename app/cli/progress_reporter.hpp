#pragma once
// Progress of a long command (a replay, a render) on stderr: a bar with the share done, the
// rate and the time left on a terminal, plain lines in a log, nothing with --quiet. Jobs
// report through util::ProgressCallback and never know which.
#include <impasto/util/progress.hpp>

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace impasto::app {

enum class ProgressStyle {
  automatic,  // a bar on a terminal, lines otherwise; only for jobs past one second
  bar,        // the bar, from the start
  lines,      // plain lines, from the start (logs, tests)
  none,       // nothing (--quiet)
};

// --quiet on the command line: no progress, no notes (ProgressStyle::none).
void set_quiet(bool quiet);
bool quiet();
// The style in force: none when quiet, else $IMPASTO_PROGRESS (auto, bar, lines or none),
// else automatic. Throws std::runtime_error for another value of the variable.
ProgressStyle progress_style();

// One job's progress. Thread-safe: update() may come from any worker thread.
class ProgressReporter {
 public:
  // job: what runs ("render"); unit: what is counted ("tiles").
  ProgressReporter(std::string job, std::string unit);
  ~ProgressReporter();  // finish()
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  void update(std::uint64_t done, std::uint64_t total);
  // Ends the bar's line (or writes the last line) when anything was shown. Idempotent.
  void finish();
  // Before a line of results on a terminal: takes the bar off its line (the next update
  // draws it again below the results).
  void clear();
  // A callback reporting here, for the job; valid while this reporter lives.
  util::ProgressCallback callback();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(std::uint64_t done, std::uint64_t total, bool last);  // under mutex_

  std::string job_, unit_;
  ProgressStyle style_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
  std::uint64_t done_ = 0, total_ = 0;
  Clock::time_point last_draw_{};
  int last_tenth_ = -1;  // lines: the last tenth of the job written
  bool wait_ = true;     // silent for the first second (automatic style)
  bool shown_ = false, finished_ = false;
};

// "12 s", "2 min 05 s", "<1 s".
std::string describe_duration(double seconds);

}  // namespace impasto::app
