#include "impasto/files/confined_path.hpp"

#include <algorithm>
#include <stdexcept>

#include "impasto/files/message_text.hpp"

namespace impasto::files {

std::filesystem::path confined_path(const std::filesystem::path& folder,
                                    const std::string& relative, const std::string& where) {
  const auto refuse = [&](const std::string& why) {
    throw std::runtime_error(where + ": " + excerpt(relative) + " " + why +
                             " (a path must stay inside " + folder.string() + ")");
  };
  if (relative.empty()) refuse("is empty");
  if (relative.find('\0') != std::string::npos) refuse("holds a NUL byte");
  const std::filesystem::path path(relative);
  if (path.is_absolute() || path.has_root_name() || path.has_root_directory())
    refuse("is an absolute path");
  for (const auto& part : path)
    if (part == "..") refuse("climbs out with '..'");
  const std::filesystem::path joined = folder / path;
  // Symlinks inside the folder are fine as long as where they lead stays inside it.
  std::error_code error;
  const auto real_folder = std::filesystem::weakly_canonical(folder, error);
  if (error) return joined;
  const auto real = std::filesystem::weakly_canonical(joined, error);
  if (error) return joined;
  const auto [end, _] =
      std::mismatch(real_folder.begin(), real_folder.end(), real.begin(), real.end());
  if (end != real_folder.end()) refuse("leads out of the folder through a symlink");
  return joined;
}

}  // namespace impasto::files
