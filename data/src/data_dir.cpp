#include "impasto/data/data_dir.hpp"

#include <cstdlib>
#include <stdexcept>

namespace impasto::data {

std::filesystem::path data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("IMPASTO_DATA_DIR"); env && *env) {
    if (fs::is_directory(env)) return env;
    throw std::runtime_error(std::string("IMPASTO_DATA_DIR is not a folder: ") + env);
  }
  for (const char* candidate : {IMPASTO_SOURCE_DATA_DIR, IMPASTO_INSTALL_DATA_DIR}) {
    if (fs::is_directory(candidate)) return candidate;
  }
  throw std::runtime_error("no Impasto data folder found; set IMPASTO_DATA_DIR");
}

}  // namespace impasto::data
