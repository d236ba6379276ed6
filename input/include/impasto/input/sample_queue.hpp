#pragma once
// A bounded queue of pen samples between reader threads and the application, which polls
// it without ever blocking on a reader.
#include <impasto/paintcore/pen_sample.hpp>

#include <cstddef>
#include <deque>
#include <mutex>
#include <vector>

namespace impasto::input {

class SampleQueue {
 public:
  // When full, the oldest sample is dropped: the newest pen state matters most.
  explicit SampleQueue(std::size_t capacity = 8192);

  void push(const paintcore::PenSample& sample);
  // Every sample queued so far, oldest first; empties the queue.
  std::vector<paintcore::PenSample> drain();
  std::size_t size() const;
  std::size_t dropped() const;

 private:
  mutable std::mutex mutex_;
  std::deque<paintcore::PenSample> samples_;
  std::size_t capacity_;
  std::size_t dropped_ = 0;
};

}  // namespace impasto::input
