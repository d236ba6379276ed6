#pragma once
// Input latency as the user sees it: from a pen sample's own time (its event's, from the
// window system) to the buffer swap of the first frame drawn after the simulation applied it.
// Samples are known by their job number in the simulation's queue (SimStats::submitted
// right after submitting); a frame knows how many jobs were applied before it uploaded.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace impasto::app::window {

class InputLatency {
 public:
  explicit InputLatency(std::size_t recent = 100) : recent_capacity_(recent) {}

  // A sample that reached the window at event_time_s was queued as job `job`.
  void submitted(std::uint64_t job, double event_time_s);
  // A frame whose upload followed the first `applied` jobs was swapped at swap_time_s (the
  // same clock as the event times).
  void shown(std::uint64_t applied, double swap_time_s);

  // Median over the last `recent` samples shown, in ms; none before the first.
  std::optional<double> recent_median_ms() const;
  // Over every sample shown since construction; q in [0, 1].
  std::optional<double> percentile_ms(double q) const;
  std::size_t shown_count() const { return all_ms_.size(); }
  std::size_t waiting() const { return waiting_.size(); }

 private:
  struct Waiting {
    std::uint64_t job;
    double event_time_s;
  };
  std::size_t recent_capacity_;
  std::deque<Waiting> waiting_;
  std::deque<double> recent_ms_;
  std::vector<double> all_ms_;
};

}  // namespace impasto::app::window
