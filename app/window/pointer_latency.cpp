#include "window/pointer_latency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "latency_lines.hpp"

namespace impasto::app::window {
namespace {

std::optional<double> percentile_of(std::vector<double> values, double q) {
  if (values.empty()) return std::nullopt;
  const auto rank = static_cast<std::size_t>(
      std::lround(std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

}  // namespace

void InputLatency::submitted(std::uint64_t job, double event_time_s) {
  waiting_.push_back({job, event_time_s});
}

void InputLatency::shown(std::uint64_t applied, double swap_time_s) {
  while (!waiting_.empty() && waiting_.front().job <= applied) {
    const double ms = 1e3 * std::max(0.0, swap_time_s - waiting_.front().event_time_s);
    waiting_.pop_front();
    all_ms_.push_back(ms);
    recent_ms_.push_back(ms);
    if (recent_ms_.size() > recent_capacity_) recent_ms_.pop_front();
  }
}

void InputLatency::dropped(std::uint64_t up_to) {
  while (!waiting_.empty() && waiting_.front().job <= up_to) waiting_.pop_front();
}

std::optional<double> InputLatency::recent_median_ms() const {
  return percentile_of({recent_ms_.begin(), recent_ms_.end()}, 0.5);
}

std::optional<double> InputLatency::recent_percentile_ms(double q) const {
  return percentile_of({recent_ms_.begin(), recent_ms_.end()}, q);
}

double InputLatency::behind_ms(double now_s) const {
  return waiting_.empty() ? 0.0 : 1e3 * std::max(0.0, now_s - waiting_.front().event_time_s);
}

std::optional<double> InputLatency::percentile_ms(double q) const {
  return percentile_of(all_ms_, q);
}

std::string pen_to_screen_text(double median_ms, double p95_ms, double behind_ms) {
  char text[96] = "pen to screen: paint to measure";
  if (median_ms >= 0.0)
    std::snprintf(text, sizeof text, "pen to screen %.0f / %.0f ms", median_ms,
                  std::max(median_ms, p95_ms));
  std::string out = text;
  if (behind_ms > kBehindShown_ms) {
    std::snprintf(text, sizeof text, ", behind %.0f ms", behind_ms);
    out += text;
  }
  return out;
}

void ViewLatency::submitted(ViewMotion kind, double event_time_s) {
  Kind& k = kinds_[index(kind)];
  k.latency.submitted(++k.submitted, event_time_s);
}

void ViewLatency::applied(ViewMotion kind) {
  Kind& k = kinds_[index(kind)];
  k.applied = k.submitted;
}

void ViewLatency::dropped(ViewMotion kind) {
  Kind& k = kinds_[index(kind)];
  k.latency.dropped(k.submitted);
  k.applied = k.submitted;
}

void ViewLatency::shown(double swap_time_s) {
  bool showed = false;
  for (Kind& k : kinds_) {
    const std::size_t before = k.latency.shown_count();
    k.latency.shown(k.applied, swap_time_s);
    showed |= k.latency.shown_count() != before;
  }
  if (showed && last_motion_swap_s_) {
    intervals_ms_.push_back(1e3 * (swap_time_s - *last_motion_swap_s_));
  }
  last_motion_swap_s_ = showed ? std::optional(swap_time_s) : std::nullopt;
}

std::string ViewLatency::report(std::vector<int> coarse_factors) const {
  // The names and events of ViewMotion's kinds, in its order.
  struct Words {
    const char* kind;
    const char* event;
    const char* events;
  };
  static constexpr std::array<Words, kViewMotions> kWords = {{
      {"zoom", "wheel click", "clicks"},
      {"rotation", "pointer move", "moves"},
      {"pan", "pointer move", "moves"},
      {"light", "pointer event", "events"},
  }};
  std::string text;
  for (std::size_t i = 0; i < kViewMotions; ++i) {
    const InputLatency& latency = kinds_[i].latency;
    if (latency.shown_count() == 0) continue;
    text += latency_line(kWords[i].kind, kWords[i].event, kWords[i].events,
                         {*latency.percentile_ms(0.5), *latency.percentile_ms(0.95),
                          static_cast<int>(latency.shown_count())}) +
            "\n";
  }
  if (text.empty()) return text;
  std::sort(coarse_factors.begin(), coarse_factors.end());
  return text +
         motion_frames_line({static_cast<int>(coarse_factors.size()),
                             coarse_factors.empty() ? 0 : coarse_factors[coarse_factors.size() / 2],
                             percentile_of(intervals_ms_, 0.5).value_or(0.0)}) +
         "\n";
}

paintcore::StepQuality CatchUp::next(paintcore::StepQuality chosen, bool enabled,
                                     double behind_ms) {
  if (!enabled || chosen == paintcore::StepQuality::fast)
    catching_up_ = false;
  else if (behind_ms > kFallenBehind_ms)
    catching_up_ = true;
  else if (behind_ms < kCaughtUp_ms)
    catching_up_ = false;
  return catching_up_ ? paintcore::StepQuality::fast : chosen;
}

}  // namespace impasto::app::window
