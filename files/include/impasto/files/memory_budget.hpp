#pragma once
// What a loader may allocate on the word of a file: declared sizes are checked against this
// before any allocation, and an allocation that still fails names what it was for.
#include <cstdint>
#include <string>

#include "impasto/files/message_text.hpp"

namespace impasto::files {

// The machine's physical memory, or $IMPASTO_MEMORY_BUDGET_MB when set (tests and small
// machines use it).
std::uint64_t memory_budget_bytes();

// Throws std::runtime_error "<where>: <what> needs N, more than the memory budget of M"
// when bytes exceed the budget.
void check_allocation(const std::string& where, const std::string& what, std::uint64_t bytes);

// The message for a std::bad_alloc caught while allocating `what` (bytes when known, else 0).
std::string out_of_memory_message(const std::string& where, const std::string& what,
                                  std::uint64_t bytes = 0);

}  // namespace impasto::files
