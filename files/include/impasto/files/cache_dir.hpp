#pragma once
// Where Impasto keeps what it can rebuild (carried flake files, trained wavelength rules):
// a private folder of the user's cache, never the data folder, the working folder or a
// folder another user can write to.
#include <cstddef>
#include <filesystem>
#include <string_view>

namespace impasto::files {

// $XDG_CACHE_HOME/impasto/<name> when XDG_CACHE_HOME is an absolute path (the XDG rule: a
// relative one is ignored), else <home>/.cache/impasto/<name> with <home> from $HOME or, if
// unset, the password database. With no home at all (a service, a sandbox), <name> inside a
// fresh folder mkdtemp made for this process (mode 0700, removed at exit): never a
// predictable name in the shared temporary folder, where another user could have planted a
// folder or a symlink.
//
// Created if missing, then checked without following links: a folder, not a symlink, owned
// by this user and writable by no one else (std::runtime_error naming it otherwise).
std::filesystem::path cache_dir(std::string_view name);

// Keeps at most `keep` entries in `folder`: the ones touched longest ago (their modification
// time, which touch_cache_entry sets on every use) are removed. Errors are ignored: a cache
// that cannot be trimmed is still a cache.
void trim_cache(const std::filesystem::path& folder, std::size_t keep);
// Marks an entry of a cache folder as just used.
void touch_cache_entry(const std::filesystem::path& entry);

}  // namespace impasto::files
