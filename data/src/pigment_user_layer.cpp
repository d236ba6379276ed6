#include "impasto/data/pigment_user_layer.hpp"

#include <cctype>
#include <ctime>
#include <sstream>
#include <stdexcept>

#include "impasto/data/pigment_library.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"

namespace impasto::data {
namespace {

namespace fs = std::filesystem;

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  }
  return true;
}

// The value of "key = value" in a flake paint file, or empty.
std::string flake_field(const std::string& text, const std::string& key) {
  return util::key_value_field(text, key);
}

// Copies a pigment's flake file (and its n,k table, named relative to it) into folder.
std::string copy_flakes(const fs::path& folder, const fs::path& flake_file) {
  const std::string text = files::read_whole_file(flake_file, "flake paint");
  const fs::path target = folder / flake_file.filename();
  if (fs::equivalent(flake_file.parent_path(), folder)) return flake_file.filename().string();
  files::write_file_atomically(target, text);
  if (const std::string table = flake_field(text, "nk_table"); !table.empty()) {
    const fs::path source = flake_file.parent_path() / table;
    if (fs::path(table).has_parent_path() || !fs::is_regular_file(source)) {
      throw std::runtime_error(flake_file.string() + ": field 'nk_table': " +
                               files::excerpt(table) + " must be a file beside the flake file");
    }
    files::write_file_atomically(folder / table, files::read_whole_file(source, "n,k table"));
  }
  return target.filename().string();
}

}  // namespace

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

fs::path save_pigment_to_folder(const fs::path& folder, Pigment pigment, bool overwrite) {
  if (pigment.name.empty()) throw std::runtime_error("a pigment needs a name");
  fs::create_directories(folder);
  const fs::path path = folder / pigment_file_name(pigment.name);
  if (fs::exists(path)) {
    std::string held;
    try {
      held = read_pigment_file(path).name;
    } catch (const std::exception&) {
    }
    if (!held.empty() && held != pigment.name) {
      throw std::runtime_error(path.string() + " holds pigment " + files::excerpt(held) +
                               "; rename one of them first");
    }
    if (!overwrite) {
      throw std::runtime_error(path.string() + " exists (use --force to replace it)");
    }
  }
  for (const auto& loaded : scan_pigment_folder(folder).pigments) {
    if (loaded.pigment.name == pigment.name && loaded.file != path) {
      throw std::runtime_error(loaded.file.string() + " already holds pigment " +
                               files::excerpt(pigment.name));
    }
  }
  if (!pigment.flakes.empty()) pigment.metadata["flakes"] = copy_flakes(folder, pigment.flakes);
  write_pigment_file(path, pigment);
  return path;
}

fs::path import_pigment_file(const fs::path& folder, const fs::path& file, bool overwrite) {
  return save_pigment_to_folder(folder, read_pigment_file(file), overwrite);
}

fs::path pigment_file_in_folder(const fs::path& folder, const std::string& name) {
  const PigmentFolderScan scan = scan_pigment_folder(folder);
  for (const auto& loaded : scan.pigments) {
    if (loaded.pigment.name == name) return loaded.file;
  }
  for (const auto& loaded : scan.pigments) {
    if (same_ignoring_case(loaded.pigment.name, name)) return loaded.file;
  }
  throw std::runtime_error("no pigment " + files::excerpt(name) + " in " + folder.string() +
                           " (only this folder's pigments can be changed)");
}

fs::path rename_pigment_in_folder(const fs::path& folder, const std::string& name,
                                  const std::string& new_name) {
  const fs::path old_file = pigment_file_in_folder(folder, name);
  Pigment pigment = read_pigment_file(old_file);
  for (const auto& loaded : scan_pigment_folder(folder).pigments) {
    if (loaded.pigment.name == new_name)
      throw std::runtime_error(loaded.file.string() + " already holds " + files::excerpt(new_name));
  }
  pigment.name = new_name;
  pigment.metadata["modified"] = utc_timestamp() + " renamed from " + name;
  const fs::path new_file = folder / pigment_file_name(new_name);
  if (new_file != old_file && fs::exists(new_file)) {
    throw std::runtime_error(new_file.string() + " exists");
  }
  if (!pigment.flakes.empty()) pigment.metadata["flakes"] = copy_flakes(folder, pigment.flakes);
  write_pigment_file(new_file, pigment);
  if (new_file != old_file) fs::remove(old_file);
  return new_file;
}

fs::path remove_pigment_from_folder(const fs::path& folder, const std::string& name) {
  const fs::path file = pigment_file_in_folder(folder, name);
  fs::remove(file);
  return file;
}

}  // namespace impasto::data
