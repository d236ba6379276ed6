#pragma once
// A fresh, empty folder under the test's temporary directory (GoogleTest's TempDir), emptied
// of what an earlier run left there.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace impasto::test {

inline std::filesystem::path scratch_folder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace impasto::test
