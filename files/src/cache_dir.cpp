#include "impasto/files/cache_dir.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace impasto::files {

std::filesystem::path cache_dir(std::string_view name) {
  const std::string folder(name);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && xdg[0] == '/')
    return std::filesystem::path(xdg) / "impasto" / folder;
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "impasto" / folder;
  return std::filesystem::temp_directory_path() /
         ("impasto-" + folder + "-" + std::to_string(getuid()));
}

}  // namespace impasto::files
