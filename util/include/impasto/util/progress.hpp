#pragma once
// A long job's progress (a replay, a whole-painting render), reported to whoever watches it:
// a terminal bar, a log line, a window, nobody. The job calls it; it never knows which.
#include <cstdint>
#include <functional>

namespace impasto::util {

// done of total units so far. Jobs that run on several threads may call it from any of them,
// so a callback must be thread-safe; an empty one is skipped.
using ProgressCallback = std::function<void(std::uint64_t done, std::uint64_t total)>;

}  // namespace impasto::util
