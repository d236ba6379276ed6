#pragma once
// The list of recently opened or saved paintings, kept in
// $XDG_CONFIG_HOME/impasto/recent.txt (~/.config when unset), newest first.
#include <filesystem>
#include <vector>

namespace impasto::session {

// $XDG_CONFIG_HOME/impasto (~/.config/impasto when unset; empty without either): where the
// window keeps what it remembers between sessions.
std::filesystem::path window_config_folder();

std::vector<std::filesystem::path> load_recent_files();
// Moves `file` to the front (at most 10 kept) and writes the list; errors are ignored (a
// read-only home must not stop painting).
void remember_recent_file(const std::filesystem::path& file);

}  // namespace impasto::session
