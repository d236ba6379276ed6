#pragma once
// Input latency as the user sees it: from a pen sample's own time (its event's, from the
// window system) to the buffer swap of the first frame drawn after the simulation applied it.
// Samples are known by their job number in the simulation's queue (session::SimStats::submitted
// right after submitting); a frame knows how many jobs were applied before it uploaded.
// ViewLatency times the view's motions the same way.
#include <impasto/paintcore/step_quality.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
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
  // The first `up_to` jobs will not be shown (they went elsewhere): they are not timed.
  void dropped(std::uint64_t up_to);

  // Median over the last `recent` samples shown, in ms; none before the first.
  std::optional<double> recent_median_ms() const;
  // The same for quantile q in [0, 1] (0.95: the status bar's second figure).
  std::optional<double> recent_percentile_ms(double q) const;
  // How far the screen is behind the pen at now_s: the age of the oldest sample submitted and
  // not yet shown (queued for the simulation, simulated or uploaded), in ms; 0 when none waits.
  double behind_ms(double now_s) const;
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

// The status bar's figure: "pen to screen 12 / 40 ms" (median / 95th percentile), then
// "behind 350 ms" while the screen is behind the pen by more than kBehindShown_ms (a frame or
// two behind is every sample's normal wait); before the first sample, how to get one.
inline constexpr double kBehindShown_ms = 50.0;
std::string pen_to_screen_text(double median_ms, double p95_ms, double behind_ms);

// Whether the simulation takes fast steps to catch up with the pen (the Brush panel's "fast
// while behind"): from when the screen is kFallenBehind_ms behind the pen until it is back
// within kCaughtUp_ms, two thresholds so that it does not switch back and forth at one.
class CatchUp {
 public:
  static constexpr double kFallenBehind_ms = 150.0;
  static constexpr double kCaughtUp_ms = 50.0;
  // The level the next pen sample steps at: `chosen`, or fast while catching up (`enabled`,
  // `behind_ms` as InputLatency::behind_ms says).
  paintcore::StepQuality next(paintcore::StepQuality chosen, bool enabled, double behind_ms);
  bool catching_up() const { return catching_up_; }

 private:
  bool catching_up_ = false;
};

// What moves the view or the light: a wheel click's zoom step, a move of a rotating (right
// button) or panning drag, a pointer event that moved the light (the Light panel's disc).
enum class ViewMotion { kZoom, kRotate, kPan, kLight };
inline constexpr std::size_t kViewMotions = 4;

// A view motion as the user waits for it: from its event's own time to the swap of the first
// frame drawn after the view took it. Each kind's events are numbered as they reach the window
// (submitted); a frame that applies them says so (applied: every one of that kind so far), and
// its swap shows them.
class ViewLatency {
 public:
  void submitted(ViewMotion kind, double event_time_s);
  void applied(ViewMotion kind);
  void dropped(ViewMotion kind);  // every one of that kind so far went elsewhere (a panel)
  void shown(double swap_time_s);
  const InputLatency& of(ViewMotion kind) const { return kinds_[index(kind)].latency; }

  // The window's exit report (latency_lines.hpp): a line for each kind with events shown,
  // then the motion frames' line (the factor of each coarse frame, in any order); empty when
  // nothing was shown.
  std::string report(std::vector<int> coarse_factors) const;
  // The time between each two swaps in a row that showed motions, ms: while a drag goes on,
  // its frame period (a move waits for the frame under way, then for its own).
  const std::vector<double>& motion_frame_intervals_ms() const { return intervals_ms_; }
  // The last swap showed a motion: one may be going on, its next events arriving while a
  // frame is drawn.
  bool moving() const { return last_motion_swap_s_.has_value(); }

 private:
  static std::size_t index(ViewMotion kind) { return static_cast<std::size_t>(kind); }
  struct Kind {
    InputLatency latency;
    std::uint64_t submitted = 0, applied = 0;
  };
  std::array<Kind, kViewMotions> kinds_;
  std::optional<double> last_motion_swap_s_;  // the last swap, if it showed a motion
  std::vector<double> intervals_ms_;
};

}  // namespace impasto::app::window
