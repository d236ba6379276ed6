#pragma once
// Where Impasto keeps what it can rebuild (carried flake files, trained wavelength rules):
// a folder of the user's cache, never the data folder or the working folder.
#include <filesystem>
#include <string_view>

namespace impasto::files {

// $XDG_CACHE_HOME/impasto/<name> when XDG_CACHE_HOME is an absolute path (the XDG rule: a
// relative one is ignored), else $HOME/.cache/impasto/<name>, else
// <temp folder>/impasto-<name>-<uid>. Looked up again at each call; not created.
std::filesystem::path cache_dir(std::string_view name);

}  // namespace impasto::files
