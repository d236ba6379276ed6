#include "impasto/data/pigment_library.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "impasto/data/data_dir.hpp"
#include "impasto/files/message_text.hpp"

namespace impasto::data {
namespace {

std::string named(const std::string& text) {
  return files::excerpt(text);
}

}  // namespace

PigmentFolderScan scan_pigment_folder(const std::filesystem::path& folder) {
  PigmentFolderScan scan;
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() == ".csv" && it->is_regular_file()) files.push_back(it->path());
  }
  if (error) {
    scan.problems.push_back(folder.string() + ": cannot list the folder (" + error.message() + ")");
    return scan;
  }
  std::sort(files.begin(), files.end());  // directory order is not deterministic
  for (const auto& file : files) {
    try {
      Pigment pigment = read_pigment_file(file);
      const auto same = std::find_if(scan.pigments.begin(), scan.pigments.end(),
                                     [&](const auto& p) { return p.pigment.name == pigment.name; });
      if (same != scan.pigments.end()) {
        scan.problems.push_back(file.string() + ": field 'name': pigment " + named(pigment.name) +
                                " is also defined in " + same->file.string() +
                                " (this file is skipped)");
        continue;
      }
      scan.pigments.push_back({std::move(pigment), file});
    } catch (const std::exception& e) {
      scan.problems.push_back(e.what());
    }
  }
  return scan;
}

PigmentLibrary PigmentLibrary::load(const std::vector<PigmentLayer>& layers) {
  PigmentLibrary library;
  library.layers_ = layers;
  std::vector<Pigment> pigments;
  for (const PigmentLayer& layer : layers) {
    if (!std::filesystem::is_directory(layer.folder)) {
      if (layer.required) {
        throw std::runtime_error(layer.folder.string() + ": not a pigment folder (" + layer.label +
                                 " layer)");
      }
      continue;
    }
    PigmentFolderScan scan = scan_pigment_folder(layer.folder);
    for (std::string& problem : scan.problems) library.problems_.push_back(std::move(problem));
    for (auto& loaded : scan.pigments) {
      const auto same = std::find_if(pigments.begin(), pigments.end(), [&](const Pigment& p) {
        return p.name == loaded.pigment.name;
      });
      const LibraryPigment origin{layer.label, loaded.file};
      if (same == pigments.end()) {
        pigments.push_back(std::move(loaded.pigment));
        library.origins_.push_back(origin);
        continue;
      }
      auto& replaced = library.origins_[static_cast<std::size_t>(same - pigments.begin())];
      library.notes_.push_back(layer.label + ": " + named(loaded.pigment.name) + " (" +
                               loaded.file.string() + ") overrides the " + replaced.layer +
                               " one (" + replaced.file.string() + ")");
      *same = std::move(loaded.pigment);
      replaced = origin;
    }
  }
  if (pigments.empty()) {
    std::string folders;
    for (const auto& layer : layers)
      folders += (folders.empty() ? "" : ", ") + layer.folder.string();
    throw std::runtime_error("no pigment loaded from " + folders);
  }
  library.database_ =
      std::make_shared<const PigmentDatabase>(PigmentDatabase::from_pigments(std::move(pigments)));
  return library;
}

const LibraryPigment* PigmentLibrary::origin(std::string_view name) const {
  const Pigment* pigment = database_->find(name);
  if (pigment == nullptr) return nullptr;
  return &origins_[static_cast<std::size_t>(pigment - database_->all().data())];
}

std::filesystem::path PigmentLibrary::user_folder() const {
  for (const auto& layer : layers_) {
    if (layer.writable) return layer.folder;
  }
  return {};
}

std::filesystem::path user_pigment_folder() {
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg && xdg[0] == '/') {
    return std::filesystem::path(xdg) / "impasto" / "pigments";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".local" / "share" / "impasto" / "pigments";
  }
  return {};
}

std::vector<std::filesystem::path> pigment_addon_folders() {
  std::vector<std::filesystem::path> folders;
  std::error_code error;
  for (const auto& entry :
       std::filesystem::directory_iterator(data_dir() / kPigmentAddonsFolder, error)) {
    if (entry.is_directory(error)) folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  return folders;
}

std::vector<PigmentLayer> standard_pigment_layers(
    const std::vector<std::filesystem::path>& extra_folders) {
  std::vector<PigmentLayer> layers{{"bundled", data_dir() / "pigments", false, true}};
  for (const auto& folder : pigment_addon_folders())
    layers.push_back({"add-on", folder, false, false});
  if (auto user = user_pigment_folder(); !user.empty())
    layers.push_back({"user", user, true, false});
  for (const auto& folder : extra_folders) layers.push_back({"--pigments", folder, false, true});
  return layers;
}

namespace {

struct ActiveLibrary {
  std::mutex mutex;
  std::vector<std::filesystem::path> extra_folders;
  std::vector<std::unique_ptr<PigmentLibrary>> loads;  // the last is current; old ones kept
};

ActiveLibrary& active() {
  static ActiveLibrary library;
  return library;
}

void report(const PigmentLibrary& library) {
  for (const auto& note : library.notes())
    std::fprintf(stderr, "pigments: note: %s\n", note.c_str());
  for (const auto& problem : library.problems())
    std::fprintf(stderr, "pigments: skipped %s\n", problem.c_str());
}

const PigmentLibrary& load_locked(ActiveLibrary& state, bool print) {
  state.loads.push_back(std::make_unique<PigmentLibrary>(
      PigmentLibrary::load(standard_pigment_layers(state.extra_folders))));
  if (print) report(*state.loads.back());
  return *state.loads.back();
}

}  // namespace

void add_pigment_folder(const std::filesystem::path& folder) {
  ActiveLibrary& state = active();
  const std::lock_guard lock(state.mutex);
  state.extra_folders.push_back(folder);
  if (!state.loads.empty()) load_locked(state, true);  // already read: read again with it
}

const PigmentLibrary& active_pigment_library() {
  ActiveLibrary& state = active();
  const std::lock_guard lock(state.mutex);
  if (state.loads.empty()) return load_locked(state, true);
  return *state.loads.back();
}

const PigmentLibrary& reload_active_pigment_library() {
  ActiveLibrary& state = active();
  const std::lock_guard lock(state.mutex);
  return load_locked(state, false);
}

}  // namespace impasto::data
