#include <impasto/input/sample_queue.hpp>

#include <stdexcept>

namespace impasto::input {

SampleQueue::SampleQueue(std::size_t capacity) : capacity_(capacity) {
  if (capacity == 0) throw std::invalid_argument("SampleQueue capacity must be positive");
}

void SampleQueue::push(const paintcore::PenSample& sample) {
  const std::lock_guard lock(mutex_);
  if (samples_.size() == capacity_) {
    samples_.pop_front();
    ++dropped_;
  }
  samples_.push_back(sample);
}

std::vector<paintcore::PenSample> SampleQueue::drain() {
  std::deque<paintcore::PenSample> taken;
  {
    const std::lock_guard lock(mutex_);
    taken.swap(samples_);
  }
  return {taken.begin(), taken.end()};
}

std::size_t SampleQueue::size() const {
  const std::lock_guard lock(mutex_);
  return samples_.size();
}

std::size_t SampleQueue::dropped() const {
  const std::lock_guard lock(mutex_);
  return dropped_;
}

}  // namespace impasto::input
