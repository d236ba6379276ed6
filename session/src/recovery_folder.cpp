#include "impasto/session/recovery_folder.hpp"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>

namespace impasto::session {
namespace {

std::filesystem::path state_home() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state == '/') return state;
  const char* home = std::getenv("HOME");
  if (!home || *home != '/') {
    const passwd* entry = ::getpwuid(::getuid());
    home = entry ? entry->pw_dir : nullptr;
  }
  if (!home || *home != '/') {
    throw std::runtime_error(
        "no recovery folder: neither XDG_STATE_HOME nor a home folder is known (set "
        "XDG_STATE_HOME)");
  }
  return std::filesystem::path(home) / ".local" / "state";
}

// mkdir -p with 0700 for what it creates.
void make_folders(const std::filesystem::path& folder) {
  std::filesystem::path built;
  for (const auto& part : folder) {
    built /= part;
    if (::mkdir(built.c_str(), 0700) != 0 && errno != EEXIST) {
      throw std::runtime_error(built.string() +
                               ": cannot create the recovery folder: " + std::strerror(errno));
    }
  }
}

}  // namespace

std::filesystem::path recovery_folder() {
  const std::filesystem::path folder = state_home() / "impasto";
  make_folders(folder);
  struct stat info {};
  if (::lstat(folder.c_str(), &info) != 0) {
    throw std::runtime_error(folder.string() + ": " + std::strerror(errno));
  }
  if (!S_ISDIR(info.st_mode)) {
    throw std::runtime_error(folder.string() +
                             ": the recovery folder is not a folder (a symlink?); remove it");
  }
  if (info.st_uid != ::getuid()) {
    throw std::runtime_error(folder.string() + ": the recovery folder belongs to another user");
  }
  if ((info.st_mode & 077) != 0 && ::chmod(folder.c_str(), 0700) != 0) {
    throw std::runtime_error(folder.string() +
                             ": cannot make the recovery folder private: " + std::strerror(errno));
  }
  return folder;
}

std::string unique_session_stem(const std::string& stem) {
  const auto now = std::chrono::system_clock::now();
  // Strictly increasing within the process, so that even two sessions in one microsecond
  // differ; the process id tells processes apart.
  static std::atomic<long long> last_micros{0};
  long long micros =
      std::chrono::duration_cast<std::chrono::microseconds>(now.time_since_epoch()).count();
  long long last = last_micros.load();
  do {
    if (micros <= last) micros = last + 1;
  } while (!last_micros.compare_exchange_weak(last, micros));
  const std::time_t seconds = static_cast<std::time_t>(micros / 1000000);
  micros %= 1000000;
  std::tm local{};
  ::localtime_r(&seconds, &local);
  char stamp[64];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  char fraction[32];
  std::snprintf(fraction, sizeof fraction, ".%06lld-%d", static_cast<long long>(micros),
                static_cast<int>(::getpid()));
  return stem + ".session-" + stamp + fraction;
}

}  // namespace impasto::session
