#include "window/pointer_latency.hpp"

#include <algorithm>
#include <cmath>

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

std::optional<double> InputLatency::recent_median_ms() const {
  return percentile_of({recent_ms_.begin(), recent_ms_.end()}, 0.5);
}

std::optional<double> InputLatency::percentile_ms(double q) const {
  return percentile_of(all_ms_, q);
}

}  // namespace impasto::app::window
