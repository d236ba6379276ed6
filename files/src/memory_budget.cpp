#include "impasto/files/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include <cstdlib>
#include <stdexcept>

namespace impasto::files {

namespace {

// Above this a limit means "none" (the kernel writes 2^63 less a page for an unset cgroup v1).
constexpr std::uint64_t kUnlimited = 1ull << 62;

std::uint64_t page_bytes() {
  const long page = ::sysconf(_SC_PAGESIZE);
  return page > 0 ? static_cast<std::uint64_t>(page) : 4096;
}

// Field `index` (0: the whole address space, 5: data and stack) of /proc/self/statm, in bytes.
std::uint64_t mapped_bytes(int index) {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  for (int i = 0; i <= index && statm >> pages; ++i) {
  }
  return statm ? pages * page_bytes() : 0;
}

// The first number in a file ("max" and anything unreadable: unlimited).
std::uint64_t number_in(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::uint64_t value = 0;
  return in >> value ? value : kUnlimited;
}

// The memory this process's cgroup may still take: limit less usage, v2 or v1.
std::uint64_t cgroup_room() {
  std::ifstream groups("/proc/self/cgroup");
  std::uint64_t room = kUnlimited;
  for (std::string line; std::getline(groups, line);) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    std::filesystem::path folder, limit, usage;
    if (controllers.empty()) {  // v2
      folder = "/sys/fs/cgroup";
      limit = "memory.max";
      usage = "memory.current";
    } else if (controllers.find("memory") != std::string::npos) {  // v1
      folder = "/sys/fs/cgroup/memory";
      limit = "memory.limit_in_bytes";
      usage = "memory.usage_in_bytes";
    } else {
      continue;
    }
    // Inside a cgroup namespace the process sees its own group at the root.
    for (const auto& at : {folder / std::filesystem::path(path).relative_path(), folder}) {
      std::error_code error;
      if (!std::filesystem::exists(at / limit, error)) continue;
      const std::uint64_t max = number_in(at / limit);
      if (max >= kUnlimited) break;
      const std::uint64_t used = number_in(at / usage);
      room = std::min(room, used < max ? max - used : 0);
      break;
    }
  }
  return room;
}

// A soft resource limit less what already counts against it (kUnlimited: none).
std::uint64_t rlimit_room(int resource, int statm_field) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY ||
      limit.rlim_cur >= kUnlimited)
    return kUnlimited;
  const std::uint64_t used = mapped_bytes(statm_field);
  return used < limit.rlim_cur ? limit.rlim_cur - used : 0;
}

}  // namespace

MemoryBudget memory_budget() {
  if (const char* mb = std::getenv("IMPASTO_MEMORY_BUDGET_MB")) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(mb, &end, 10);
    if (end != mb && *end == '\0' && value > 0 && value < (kUnlimited >> 20))
      return {value << 20, "IMPASTO_MEMORY_BUDGET_MB"};
  }
  MemoryBudget budget{4ull << 30, "a guess of 4 GiB (the machine's memory is unknown)"};
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  if (pages > 0) budget = {static_cast<std::uint64_t>(pages) * page_bytes(), "physical memory"};
  const auto lower = [&](std::uint64_t bytes, const char* source) {
    if (bytes < budget.bytes) budget = {bytes, source};
  };
  lower(rlimit_room(RLIMIT_AS, 0), "ulimit -v (RLIMIT_AS) less what is mapped");
  lower(rlimit_room(RLIMIT_DATA, 5), "ulimit -d (RLIMIT_DATA) less what is in use");
  lower(cgroup_room(), "the cgroup's memory limit less its usage");
  return budget;
}

void check_allocation(const std::string& where, const std::string& what, std::uint64_t bytes) {
  const MemoryBudget budget = memory_budget();
  if (bytes > budget.bytes)
    throw std::runtime_error(where + ": " + what + " needs " + describe_bytes(bytes) +
                             ", more than the memory budget of " + describe_bytes(budget.bytes) +
                             " (set by " + budget.source + ")");
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

std::string error_text(const std::exception& error) {
  if (dynamic_cast<const std::bad_alloc*>(&error) == nullptr) return error.what();
  const MemoryBudget budget = memory_budget();
  return "out of memory (the budget: " + describe_bytes(budget.bytes) + ", set by " +
         budget.source + ")";
}

std::string out_of_memory_message(const std::string& where, const std::string& what,
                                  std::uint64_t bytes) {
  std::string message = where + ": out of memory allocating " + what;
  if (bytes > 0) message += " (" + describe_bytes(bytes) + ")";
  return message;
}

}  // namespace impasto::files
