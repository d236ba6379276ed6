#include "impasto/files/memory_budget.hpp"

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

namespace impasto::files {

std::uint64_t memory_budget_bytes() {
  if (const char* mb = std::getenv("IMPASTO_MEMORY_BUDGET_MB")) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(mb, &end, 10);
    if (end != mb && *end == '\0' && value > 0) return value << 20;
  }
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return static_cast<std::uint64_t>(pages) * page;
  return 4ull << 30;
}

void check_allocation(const std::string& where, const std::string& what, std::uint64_t bytes) {
  const std::uint64_t budget = memory_budget_bytes();
  if (bytes > budget)
    throw std::runtime_error(where + ": " + what + " needs " + describe_bytes(bytes) +
                             ", more than the memory budget of " + describe_bytes(budget));
}

void check_decoded_size(const std::string& where, const std::string& what,
                        std::uint64_t decoded_bytes, std::uint64_t file_bytes) {
  // 1 KiB of slack for headers and tables that are not deflated.
  if (decoded_bytes > kMaxDeflateRatio * file_bytes + 1024)
    throw std::runtime_error(where + ": " + what + " declares at least " +
                             describe_bytes(decoded_bytes) + " of data, more than a file of " +
                             describe_bytes(file_bytes) + " can hold (deflate expands at most " +
                             std::to_string(kMaxDeflateRatio) + ":1; a damaged or crafted header)");
  check_allocation(where, what, decoded_bytes);
}

std::string out_of_memory_message(const std::string& where, const std::string& what,
                                  std::uint64_t bytes) {
  std::string message = where + ": out of memory allocating " + what;
  if (bytes > 0) message += " (" + describe_bytes(bytes) + ")";
  return message;
}

}  // namespace impasto::files
