#include "impasto/files/memory_budget.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace impasto::files {
namespace {

std::string error_of(void (*check)()) {
  try {
    check();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(MemoryBudget, TheEnvironmentSetsTheBudget) {
  ::setenv("IMPASTO_MEMORY_BUDGET_MB", "64", 1);
  EXPECT_EQ(memory_budget_bytes(), 64ull << 20);
  EXPECT_EQ(error_of([] { check_allocation("a.png", "the image", 100'000'000); }),
            "a.png: the image needs 100.0 MB, more than the memory budget of 67.1 MB (set by "
            "IMPASTO_MEMORY_BUDGET_MB)");
  EXPECT_EQ(error_of([] { check_allocation("a.png", "the image", 1'000'000); }), "");
  ::unsetenv("IMPASTO_MEMORY_BUDGET_MB");
  EXPECT_GT(memory_budget_bytes(), 64ull << 20);  // the machine's memory
}

// `ulimit -v` (RLIMIT_AS) lowers the budget to the address space it leaves, and a check
// names it: a machine's RAM is no budget for a process limited to a fraction of it.
TEST(MemoryBudget, TheProcesssAddressSpaceLimitLowersTheBudget) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory: no RLIMIT_AS fits it";
#else
  ::unsetenv("IMPASTO_MEMORY_BUDGET_MB");
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the limit stays with the child
    std::ifstream statm("/proc/self/statm");
    unsigned long long pages = 0;
    statm >> pages;
    const rlim_t mapped = pages * static_cast<unsigned long long>(::sysconf(_SC_PAGESIZE));
    const rlimit limit{mapped + (300ull << 20), mapped + (300ull << 20)};
    ::setrlimit(RLIMIT_AS, &limit);
    const MemoryBudget budget = memory_budget();
    std::string error;
    try {
      check_allocation("a.impasto", "the canvas", 1ull << 30);
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
    const std::string report = std::to_string(budget.bytes) + "\n" + budget.source + "\n" + error;
    [[maybe_unused]] const auto written = ::write(pipe_ends[1], report.data(), report.size());
    ::_exit(0);
  }
  ::close(pipe_ends[1]);
  std::string report;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;) report.append(buffer, n);
  ::close(pipe_ends[0]);
  ::waitpid(child, nullptr, 0);
  const std::uint64_t bytes = std::stoull(report);
  EXPECT_LE(bytes, 300ull << 20) << report;
  EXPECT_GT(bytes, 200ull << 20) << report;
  EXPECT_NE(report.find("ulimit -v (RLIMIT_AS)"), std::string::npos) << report;
  EXPECT_NE(report.find("a.impasto: the canvas needs 1073.7 MB, more than the memory budget of"),
            std::string::npos)
      << report;
#endif
}

TEST(MemoryBudget, ADeclaredSizeMustFitTheFileAtDeflatesRatio) {
  EXPECT_NE(error_of([] { check_decoded_size("a.png", "IHDR", 1'250'000'000, 68); })
                .find("a.png: IHDR declares at least 1250.0 MB of data, more than a file of 68 "
                      "bytes can hold"),
            std::string::npos);
  EXPECT_EQ(error_of([] { check_decoded_size("a.png", "IHDR", kMaxDeflateRatio * 1000, 1000); }),
            "");
}

TEST(MemoryBudget, OutOfMemoryNamesWhatAndHowMuch) {
  EXPECT_EQ(out_of_memory_message("a.impasto", "the canvas", 2'000'000'000),
            "a.impasto: out of memory allocating the canvas (2000.0 MB)");
}

}  // namespace
}  // namespace impasto::files
