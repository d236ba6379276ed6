#include "window/recent_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace impasto::app::window {
namespace {

constexpr std::size_t kMaxRecent = 10;

std::filesystem::path recent_list_path() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
    return std::filesystem::path(config) / "impasto" / "recent.txt";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "impasto" / "recent.txt";
  }
  return {};
}

}  // namespace

std::vector<std::filesystem::path> load_recent_files() {
  std::vector<std::filesystem::path> files;
  const auto list = recent_list_path();
  if (list.empty()) return files;
  std::ifstream in(list);
  std::string line;
  while (std::getline(in, line) && files.size() < kMaxRecent) {
    if (!line.empty()) files.emplace_back(line);
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
  std::ofstream out(list);
  for (const auto& f : files) out << f.string() << "\n";
}

}  // namespace impasto::app::window
