#include "impasto/files/data_dir.hpp"

#include <cstdlib>
#include <stdexcept>
#include <system_error>

namespace impasto::files {
namespace fs = std::filesystem;

fs::path installed_data_dir(const fs::path& executable) {
  return executable.parent_path().parent_path() / "share" / "impasto";
}

namespace {

// Whether `file` is inside `folder` (both made absolute, symlinks resolved where they exist).
bool lies_in(const fs::path& file, const fs::path& folder) {
  if (folder.empty()) return false;
  std::error_code error;
  const fs::path f = fs::weakly_canonical(file, error);
  if (error) return false;
  const fs::path d = fs::weakly_canonical(folder, error);
  if (error) return false;
  const fs::path relative = f.lexically_relative(d);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

fs::path find_data_dir(const DataDirCandidates& candidates) {
  if (!candidates.environment.empty()) {
    if (fs::is_directory(candidates.environment)) return candidates.environment;
    throw std::runtime_error("IMPASTO_DATA_DIR is not a folder: " + candidates.environment);
  }
  std::string tried;
  const auto try_folder = [&tried](const fs::path& folder) {
    if (folder.empty()) return false;
    std::error_code error;
    if (fs::is_directory(folder, error)) return true;
    tried += (tried.empty() ? "" : ", ") + folder.string();
    return false;
  };
  if (!candidates.executable.empty()) {
    const fs::path installed = installed_data_dir(candidates.executable);
    if (try_folder(installed)) return installed;
  }
  if (!candidates.source_data_dir.empty() &&
      (candidates.executable.empty() || lies_in(candidates.executable, candidates.build_dir))) {
    if (try_folder(candidates.source_data_dir)) return candidates.source_data_dir;
  }
  throw std::runtime_error("no Impasto data folder found (looked in " +
                           (tried.empty() ? std::string("nothing") : tried) +
                           "); set IMPASTO_DATA_DIR");
}

fs::path data_dir() {
  DataDirCandidates candidates;
  if (const char* env = std::getenv("IMPASTO_DATA_DIR"); env && *env) candidates.environment = env;
  std::error_code error;
  candidates.executable = fs::read_symlink("/proc/self/exe", error);  // Linux: the real file
  if (error) candidates.executable.clear();
  candidates.source_data_dir = IMPASTO_SOURCE_DATA_DIR;
  candidates.build_dir = IMPASTO_BUILD_DIR;
  return find_data_dir(candidates);
}

}  // namespace impasto::files
