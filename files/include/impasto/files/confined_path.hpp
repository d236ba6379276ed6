#pragma once
// A path read from a data file (a pigment's "# flakes:" line, a flake paint's n,k table)
// names a file inside that data file's library folder: not absolute, no "..", and no symlink
// that leads out of the folder.
#include <filesystem>
#include <string>

namespace impasto::files {

// folder / relative, or std::runtime_error "<where>: <relative> ...: must stay inside <folder>".
// `where` is the file and field that named the path.
std::filesystem::path confined_path(const std::filesystem::path& folder,
                                    const std::string& relative, const std::string& where);

}  // namespace impasto::files
