#include "window/config_files.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "impasto/files/atomic_file.hpp"
#include "impasto/session/recent_files.hpp"

namespace impasto::app::window {

std::string read_config_text(const std::string& file_name, std::size_t max_bytes,
                             std::string& warning) {
  const std::filesystem::path folder = session::window_config_folder();
  if (folder.empty()) return {};
  const std::filesystem::path file = folder / file_name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return {};
  if (std::filesystem::file_size(file, error) > max_bytes) {
    warning = file.string() + ": larger than " + std::to_string(max_bytes / 1024) + " kB, not read";
    return {};
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_config_text(const std::string& file_name, const std::string& text) {
  const std::filesystem::path folder = session::window_config_folder();
  if (folder.empty())
    throw std::runtime_error("cannot save " + file_name +
                             ": neither XDG_CONFIG_HOME nor HOME is set");
  std::filesystem::create_directories(folder);
  files::write_file_atomically(folder / file_name, text);
}

}  // namespace impasto::app::window
