#include "impasto/files/confined_path.hpp"

#include <algorithm>
#include <stdexcept>

#include "impasto/files/message_text.hpp"

namespace impasto::files {
namespace {

bool inside(const std::filesystem::path& folder, const std::filesystem::path& path) {
  const auto [end, _] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return end == folder.end() || (std::next(end) == folder.end() && end->empty());
}

std::filesystem::path absolute_normal(const std::filesystem::path& path) {
  return std::filesystem::absolute(path).lexically_normal();
}

}  // namespace

std::filesystem::path confined_path(const std::filesystem::path& library,
                                    const std::filesystem::path& relative_to,
                                    const std::string& relative, const std::string& where) {
  const auto refuse = [&](const std::string& why) {
    throw std::runtime_error(where + ": " + excerpt(relative) + " " + why +
                             " (a path must stay inside " + library.string() + ")");
  };
  if (relative.empty()) refuse("is empty");
  if (relative.find('\0') != std::string::npos) refuse("holds a NUL byte");
  const std::filesystem::path path(relative);
  if (path.is_absolute() || path.has_root_name() || path.has_root_directory())
    refuse("is an absolute path");
  const std::filesystem::path joined = relative_to / path;
  const auto root = absolute_normal(library);
  if (!inside(root, absolute_normal(joined))) refuse("climbs out with '..'");
  // Symlinks are fine as long as where they lead stays inside the library.
  std::error_code error;
  const auto real_root = std::filesystem::weakly_canonical(root, error);
  if (error) return joined;
  const auto real = std::filesystem::weakly_canonical(joined, error);
  if (error) return joined;
  if (!inside(real_root, real)) refuse("leads out of the library through a symlink");
  return joined;
}

}  // namespace impasto::files
