#pragma once
// A test's own user pigment layer: for the object's life XDG_DATA_HOME points into a fresh
// folder under the system's temporary directory (named NAME_PID, so that test programs run
// side by side keep apart) and the active pigment library is read from there; after, the
// previous XDG_DATA_HOME is back, the library read again and the folder removed.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "impasto/data/pigment_library.hpp"

namespace impasto::test {

class UserPigmentFolder {
 public:
  explicit UserPigmentFolder(const std::string& name)
      : dir_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    if (const char* old = std::getenv("XDG_DATA_HOME")) saved_ = old;
    setenv("XDG_DATA_HOME", (dir_ / "xdg").c_str(), 1);
    data::reload_active_pigment_library();
  }
  ~UserPigmentFolder() {
    if (saved_.empty()) {
      unsetenv("XDG_DATA_HOME");
    } else {
      setenv("XDG_DATA_HOME", saved_.c_str(), 1);
    }
    data::reload_active_pigment_library();
    std::filesystem::remove_all(dir_);
  }
  UserPigmentFolder(const UserPigmentFolder&) = delete;
  UserPigmentFolder& operator=(const UserPigmentFolder&) = delete;

  // The test's folder, and the user layer's pigment folder in it.
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path user() const { return dir_ / "xdg" / "impasto" / "pigments"; }

 private:
  std::filesystem::path dir_;
  std::string saved_;
};

}  // namespace impasto::test
