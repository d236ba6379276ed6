#pragma once
// A path read from a data file (a pigment's "# flakes:" line, a flake paint's n,k table)
// names a file inside that data file's library folder: not absolute, not climbing out with
// "..", and not through a symlink that leads out of the library.
#include <filesystem>
#include <string>

namespace impasto::files {

// relative_to / relative, which must lie inside `library` (relative_to itself is inside it);
// else std::runtime_error "<where>: '<relative>' ... (a path must stay inside <library>)".
// `where` is the file and field that named the path.
std::filesystem::path confined_path(const std::filesystem::path& library,
                                    const std::filesystem::path& relative_to,
                                    const std::string& relative, const std::string& where);

// The same with the library the folder of the naming file itself.
inline std::filesystem::path confined_path(const std::filesystem::path& folder,
                                           const std::string& relative, const std::string& where) {
  return confined_path(folder, folder, relative, where);
}

}  // namespace impasto::files
