#include "impasto/session/recent_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "impasto/files/atomic_file.hpp"
#include "impasto/util/text.hpp"

namespace impasto::session {
namespace {

constexpr std::size_t kMaxRecent = 10;
// The list's first line since names may hold any byte: each name on one line, its control
// characters and '%' written as %XX (util::line_encoded). A list without it (older) holds
// names as they are.
constexpr std::string_view kHeader = "# impasto-recent 2";

std::filesystem::path recent_list_path() {
  const auto folder = window_config_folder();
  return folder.empty() ? folder : folder / "recent.txt";
}

}  // namespace

std::filesystem::path window_config_folder() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
    return std::filesystem::path(config) / "impasto";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "impasto";
  }
  return {};
}

std::vector<std::filesystem::path> load_recent_files() {
  std::vector<std::filesystem::path> files;
  const auto list = recent_list_path();
  if (list.empty()) return files;
  std::ifstream in(list);
  std::string line;
  bool is_encoded = false;
  while (std::getline(in, line) && files.size() < kMaxRecent) {
    if (line == kHeader) {
      is_encoded = true;
      continue;
    }
    if (!line.empty()) files.emplace_back(is_encoded ? util::line_decoded(line) : line);
  }
  return files;
}

void remember_recent_file(const std::filesystem::path& file) {
  const auto list = recent_list_path();
  if (list.empty()) return;
  std::error_code error;
  const auto absolute = std::filesystem::absolute(file, error);
  auto files = load_recent_files();
  std::erase(files, absolute);
  files.insert(files.begin(), absolute);
  if (files.size() > kMaxRecent) files.resize(kMaxRecent);
  std::filesystem::create_directories(list.parent_path(), error);
  std::string text = std::string(kHeader) + "\n";
  for (const auto& f : files) text += util::line_encoded(f.string()) + "\n";
  try {
    impasto::files::write_file_atomically(list, text);
  } catch (const std::runtime_error&) {
    // The list is a convenience: a read-only or full home keeps the old one.
  }
}

}  // namespace impasto::session
