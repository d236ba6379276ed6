#pragma once
// The window's own small settings files in window_config_folder() (~/.config/impasto): read
// whole with a bound, written atomically.
#include <cstddef>
#include <string>

namespace impasto::app::window {

// The file's text, or why not (in `warning`): missing (or no config folder) is empty and no
// warning; larger than `max_bytes`, not read.
std::string read_config_text(const std::string& file_name, std::size_t max_bytes,
                             std::string& warning);
// Written atomically into the folder (made when missing); throws std::runtime_error naming
// the file when it cannot be.
void write_config_text(const std::string& file_name, const std::string& text);

}  // namespace impasto::app::window
