// The cache folder (files/cache_dir.hpp): the user's own, created private, never a symlink or
// a folder another user owns; a cache trimmed to its most recently used entries.
#include "impasto/files/cache_dir.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include "../common/scoped_env.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "temp_folder.hpp"

namespace impasto::files {
namespace {

namespace fs = std::filesystem;
using impasto::test::ScopedEnv;

TEST(CacheDir, IsCreatedPrivateUnderXdgCacheHome) {
  test::TempFolder temp;
  ScopedEnv xdg("XDG_CACHE_HOME", temp.path().string());
  const fs::path folder = cache_dir("rules");
  EXPECT_EQ(folder, temp.path() / "impasto" / "rules");
  EXPECT_TRUE(fs::is_directory(folder));
  struct stat info {};
  ASSERT_EQ(stat(folder.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & (S_IWGRP | S_IWOTH), 0u);
}

TEST(CacheDir, AGroupWritableFolderOfOursIsMadePrivate) {
  test::TempFolder temp;
  ScopedEnv xdg("XDG_CACHE_HOME", temp.path().string());
  fs::create_directories(temp / "impasto/rules");
  fs::permissions(temp / "impasto/rules", fs::perms::all);
  cache_dir("rules");
  EXPECT_EQ(fs::status(temp / "impasto/rules").permissions() & fs::perms::others_write,
            fs::perms::none);
}

// A symlink planted where the cache folder goes is refused, not followed: nothing lands in the
// folder it points at.
TEST(CacheDir, APlantedSymlinkIsRefusedNotFollowed) {
  test::TempFolder temp;
  ScopedEnv xdg("XDG_CACHE_HOME", (temp / "cache").string());
  fs::create_directories(temp / "victim");
  fs::create_directories(temp / "cache/impasto");
  fs::create_directory_symlink(temp / "victim", temp / "cache/impasto/carried-flakes");
  try {
    cache_dir("carried-flakes");
    ADD_FAILURE() << "a symlinked cache folder was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("carried-flakes: the cache folder is not a folder"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_empty(temp / "victim"));
}

// With HOME unset the cache is not a predictable name in the shared temporary folder (where
// another user may have planted a symlink) but the user's own home from the password
// database, or a fresh private folder.
TEST(CacheDir, WithoutHomeItIsNotAPredictableSharedFolder) {
  ScopedEnv xdg("XDG_CACHE_HOME", std::nullopt);
  ScopedEnv home("HOME", std::nullopt);
  const fs::path old_name =
      fs::temp_directory_path() / ("impasto-carried-flakes-" + std::to_string(getuid()));
  const fs::path folder = cache_dir("carried-flakes");
  EXPECT_NE(folder, old_name);
  struct stat info {};
  ASSERT_EQ(lstat(folder.c_str(), &info), 0);
  EXPECT_TRUE(S_ISDIR(info.st_mode));
  EXPECT_EQ(info.st_uid, getuid());
}

TEST(CacheDir, TrimKeepsTheMostRecentlyUsedEntries) {
  test::TempFolder temp;
  const auto now = fs::file_time_type::clock::now();
  for (int i = 0; i < 6; ++i) {
    const fs::path entry = temp / ("entry" + std::to_string(i));
    fs::create_directory(entry);
    std::ofstream(entry / "f") << i;
    fs::last_write_time(entry, now - std::chrono::hours(10 - i));
  }
  touch_cache_entry(temp / "entry0");  // the oldest, used just now
  trim_cache(temp.path(), 3);
  EXPECT_TRUE(fs::exists(temp / "entry0"));
  EXPECT_TRUE(fs::exists(temp / "entry4"));
  EXPECT_TRUE(fs::exists(temp / "entry5"));
  for (int i : {1, 2, 3}) EXPECT_FALSE(fs::exists(temp / ("entry" + std::to_string(i)))) << i;
}

}  // namespace
}  // namespace impasto::files
