#pragma once
// What a loader may allocate on the word of a file: declared sizes are checked against this
// before any allocation, and an allocation that still fails names what it was for.
#include <cstdint>
#include <exception>
#include <string>

#include "impasto/files/message_text.hpp"

namespace impasto::files {

// What this process may allocate, and what set it: $IMPASTO_MEMORY_BUDGET_MB when set (tests
// and small machines use it), else the smallest of the machine's physical memory, the
// address space `ulimit -v` leaves (RLIMIT_AS less what is mapped now), the data segment's
// (RLIMIT_DATA) and the cgroup's memory limit less its usage (a container, a systemd unit).
struct MemoryBudget {
  std::uint64_t bytes = 0;
  std::string source;  // "physical memory", "ulimit -v (RLIMIT_AS)", ...
};
MemoryBudget memory_budget();
inline std::uint64_t memory_budget_bytes() {
  return memory_budget().bytes;
}

// Throws std::runtime_error "<where>: <what> needs N, more than the memory budget of M (set
// by SOURCE)" when bytes exceed the budget.
void check_allocation(const std::string& where, const std::string& what, std::uint64_t bytes);

// A compressed file (PNG: deflate) declaring `decoded_bytes` of contents in `file_bytes`:
// deflate expands at most 1032:1, so more is a crafted header, refused naming `what`; then
// the memory budget. Throws std::runtime_error "<where>: <what> ...".
inline constexpr std::uint64_t kMaxDeflateRatio = 1032;
void check_decoded_size(const std::string& where, const std::string& what,
                        std::uint64_t decoded_bytes, std::uint64_t file_bytes);

// An exception's text for a message that adds where it happened: a std::bad_alloc reads "out
// of memory (the budget: N, set by SOURCE)", never its bare name.
std::string error_text(const std::exception& error);

// The message for a std::bad_alloc caught while allocating `what` (bytes when known, else 0).
std::string out_of_memory_message(const std::string& where, const std::string& what,
                                  std::uint64_t bytes = 0);

}  // namespace impasto::files
