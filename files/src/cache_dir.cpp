#include "impasto/files/cache_dir.hpp"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace impasto::files {
namespace {

namespace fs = std::filesystem;

// The user's home: $HOME, else the password database's entry (empty if neither).
fs::path home_folder() {
  if (const char* home = std::getenv("HOME"); home && home[0] == '/') return home;
  std::vector<char> buffer(16384);
  passwd entry{};
  passwd* found = nullptr;
  if (getpwuid_r(getuid(), &entry, buffer.data(), buffer.size(), &found) == 0 && found &&
      found->pw_dir && found->pw_dir[0] == '/')
    return found->pw_dir;
  return {};
}

// This process's private folder when there is no home: made once by mkdtemp (0700), removed
// with everything in it when the process exits.
fs::path process_private_folder() {
  static std::once_flag once;
  static fs::path folder;
  std::call_once(once, [] {
    std::string pattern = (fs::temp_directory_path() / "impasto-cache-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot make a private cache folder in " +
                               fs::temp_directory_path().string());
    folder = pattern;
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(folder, ignored);
    });
  });
  return folder;
}

// A folder this user owns, reached without a symlink at its last step, that no one else may
// write to (group and others' write bits are cleared if this user set them).
void check_private(const fs::path& folder) {
  struct stat info {};
  if (lstat(folder.c_str(), &info) != 0)
    throw std::runtime_error(folder.string() + ": cannot use the cache folder");
  if (S_ISLNK(info.st_mode) || !S_ISDIR(info.st_mode))
    throw std::runtime_error(
        folder.string() + ": the cache folder is not a folder (a symlink or a file stands there)");
  if (info.st_uid != getuid())
    throw std::runtime_error(folder.string() + ": the cache folder belongs to another user");
  if ((info.st_mode & (S_IWGRP | S_IWOTH)) != 0 &&
      chmod(folder.c_str(), info.st_mode & ~(S_IWGRP | S_IWOTH) & 07777) != 0)
    throw std::runtime_error(folder.string() + ": the cache folder is writable by others");
}

}  // namespace

fs::path cache_dir(std::string_view name) {
  const std::string folder(name);
  fs::path path;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && xdg[0] == '/')
    path = fs::path(xdg) / "impasto" / folder;
  else if (const fs::path home = home_folder(); !home.empty())
    path = home / ".cache" / "impasto" / folder;
  else
    path = process_private_folder() / folder;
  std::error_code error;
  fs::create_directories(path, error);
  check_private(path.parent_path());
  check_private(path);
  return path;
}

void trim_cache(const fs::path& folder, std::size_t keep) {
  std::vector<std::pair<fs::file_time_type, fs::path>> entries;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    std::error_code time_error;
    const auto time = it->symlink_status(time_error).type() == fs::file_type::directory
                          ? fs::last_write_time(it->path(), time_error)
                          : fs::file_time_type::min();
    entries.emplace_back(time_error ? fs::file_time_type::min() : time, it->path());
  }
  if (entries.size() <= keep) return;
  std::sort(entries.begin(), entries.end());
  for (std::size_t i = 0; i + keep < entries.size(); ++i) fs::remove_all(entries[i].second, error);
}

void touch_cache_entry(const fs::path& entry) {
  std::error_code ignored;
  fs::last_write_time(entry, fs::file_time_type::clock::now(), ignored);
}

}  // namespace impasto::files
