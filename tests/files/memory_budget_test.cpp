#include "impasto/files/memory_budget.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

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
            "a.png: the image needs 100.0 MB, more than the memory budget of 67.1 MB");
  EXPECT_EQ(error_of([] { check_allocation("a.png", "the image", 1'000'000); }), "");
  ::unsetenv("IMPASTO_MEMORY_BUDGET_MB");
  EXPECT_GT(memory_budget_bytes(), 64ull << 20);  // the machine's memory
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
