#include "window/file_browser_model.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "impasto/files/atomic_file.hpp"
#include "impasto/util/text.hpp"

namespace impasto::app::window {
namespace {

namespace fs = std::filesystem;

// The kinds of file Impasto itself reads and writes: a name ending in one of them was meant
// for another dialog, and its extension is replaced rather than kept.
bool is_impasto_kind(const std::string& extension) {
  static const std::vector<std::string> kinds{".impasto", ".png", ".exr", ".strokes"};
  return std::find(kinds.begin(), kinds.end(), util::ascii_lowercase(extension)) != kinds.end();
}

constexpr FilePurpose kAllFilePurposes[] = {FilePurpose::kOpenPainting, FilePurpose::kSavePainting,
                                            FilePurpose::kExportImage, FilePurpose::kOpenStrokes,
                                            FilePurpose::kOpenReference};

}  // namespace

std::vector<FileFilter> filters_for(FilePurpose purpose) {
  const FileFilter all{"All files", {}};
  switch (purpose) {
    case FilePurpose::kOpenPainting:
      return {{"Painting (*.impasto)", {".impasto"}, {".palette.impasto"}}, all};
    case FilePurpose::kSavePainting:
      return {{"Painting (*.impasto)", {".impasto"}, {".palette.impasto"}}};
    case FilePurpose::kExportImage:
      return {{"PNG image (*.png)", {".png"}}, {"OpenEXR image (*.exr)", {".exr"}}};
    case FilePurpose::kOpenStrokes:
      return {{"Strokes (*.strokes, *.dat, *.svc)", {".strokes", ".dat", ".svc"}}, all};
    case FilePurpose::kOpenReference:
      return {{"Picture (*.png, *.jpg, *.jpeg)", {".png", ".jpg", ".jpeg"}}, all};
  }
  return {all};
}

bool writes_file(FilePurpose purpose) {
  return purpose == FilePurpose::kSavePainting || purpose == FilePurpose::kExportImage;
}

std::string folder_key(FilePurpose purpose) {
  switch (purpose) {
    case FilePurpose::kOpenPainting:
    case FilePurpose::kSavePainting:
      return "painting";
    case FilePurpose::kExportImage:
      return "export";
    case FilePurpose::kOpenStrokes:
      return "strokes";
    case FilePurpose::kOpenReference:
      return "reference";
  }
  return "other";
}

bool filter_matches(const FileFilter& filter, const fs::path& file) {
  if (filter.extensions.empty()) return true;
  const std::string name = util::ascii_lowercase(file.filename().string());
  for (const std::string& ending : filter.excluded_endings) {
    if (name.ends_with(ending)) return false;
  }
  const std::string extension = util::ascii_lowercase(file.extension().string());
  return std::find(filter.extensions.begin(), filter.extensions.end(), extension) !=
         filter.extensions.end();
}

fs::path with_filter_extension(const fs::path& name, const FileFilter& filter) {
  if (filter.extensions.empty() || name.empty() || filter_matches(filter, name)) return name;
  fs::path file = name;
  if (is_impasto_kind(file.extension().string())) {
    file.replace_extension(filter.extensions.front());
  } else {
    file += filter.extensions.front();
  }
  return file;
}

std::vector<FolderEntry> list_folder(const fs::path& folder, const FileFilter& filter,
                                     bool show_hidden, std::string* error) {
  std::vector<FolderEntry> entries;
  std::error_code code;
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, code);
  for (; !code && it != fs::directory_iterator(); it.increment(code)) {
    const fs::directory_entry& entry = *it;
    FolderEntry item;
    item.name = entry.path().filename().string();
    if (!show_hidden && !item.name.empty() && item.name.front() == '.') continue;
    std::error_code kind_error;
    item.is_folder = entry.is_directory(kind_error);  // follows links, as a shell does
    if (!item.is_folder) {
      if (!filter_matches(filter, item.name)) continue;
      item.size_bytes = entry.file_size(kind_error);
      if (kind_error) item.size_bytes = 0;
    }
    entries.push_back(std::move(item));
  }
  if (code && error) *error = "cannot read the folder " + folder.string() + ": " + code.message();
  std::sort(entries.begin(), entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    if (a.is_folder != b.is_folder) return a.is_folder;
    const std::string la = util::ascii_lowercase(a.name), lb = util::ascii_lowercase(b.name);
    return la != lb ? la < lb : a.name < b.name;
  });
  return entries;
}

fs::path home_folder() {
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home);
  std::error_code error;
  return fs::current_path(error);
}

fs::path resolve_typed_path(const fs::path& folder, const std::string& typed) {
  fs::path path;
  if (typed == "~") {
    path = home_folder();
  } else if (typed.rfind("~/", 0) == 0) {
    path = home_folder() / typed.substr(2);
  } else {
    path = fs::path(typed);
    if (path.is_relative()) path = folder / path;
  }
  path = path.lexically_normal();
  // "/a/b/" normalises to "/a/b/": the folder itself, without the empty last part.
  if (path.has_relative_path() && path.filename().empty()) path = path.parent_path();
  return path;
}

std::string proposed_file_name(FilePurpose purpose, const std::optional<fs::path>& painting) {
  const std::string stem = painting ? painting->stem().string() : std::string("Untitled");
  switch (purpose) {
    case FilePurpose::kSavePainting:
      return painting ? painting->filename().string() : stem + ".impasto";
    case FilePurpose::kExportImage:
      return stem + filters_for(purpose).front().extensions.front();
    case FilePurpose::kOpenPainting:
    case FilePurpose::kOpenStrokes:
    case FilePurpose::kOpenReference:
      return {};
  }
  return {};
}

FolderMemory::FolderMemory(fs::path file) : file_(std::move(file)) {
  if (file_.empty()) return;
  std::ifstream in(file_);
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab == std::string::npos || tab == 0 || tab + 1 == line.size()) continue;
    folders_[line.substr(0, tab)] = fs::path(line.substr(tab + 1));
  }
}

std::optional<fs::path> FolderMemory::folder_for(FilePurpose purpose) const {
  const auto it = folders_.find(folder_key(purpose));
  std::error_code error;
  if (it == folders_.end() || !fs::is_directory(it->second, error)) return std::nullopt;
  return it->second;
}

void FolderMemory::remember(FilePurpose purpose, const fs::path& folder) {
  std::error_code error;
  const fs::path absolute = fs::absolute(folder, error).lexically_normal();
  if (error || absolute.empty()) return;
  folders_[folder_key(purpose)] = absolute;
  if (file_.empty()) return;
  std::string text;
  for (const auto& [key, path] : folders_) text += key + "\t" + path.string() + "\n";
  fs::create_directories(file_.parent_path(), error);
  try {
    impasto::files::write_file_atomically(file_, text);
  } catch (const std::runtime_error&) {
    // A read-only or full config folder: the folder is remembered for this session only.
  }
}

std::vector<fs::path> FolderMemory::folders() const {
  std::vector<fs::path> folders;
  for (const FilePurpose purpose : kAllFilePurposes) {
    const auto folder = folder_for(purpose);
    if (folder && std::find(folders.begin(), folders.end(), *folder) == folders.end()) {
      folders.push_back(*folder);
    }
  }
  return folders;
}

fs::path starting_folder(const FolderMemory& memory, FilePurpose purpose,
                         const std::optional<fs::path>& painting) {
  std::error_code error;
  std::optional<fs::path> beside;
  if (painting && fs::is_directory(fs::absolute(*painting, error).parent_path(), error))
    beside = fs::absolute(*painting, error).parent_path();
  // A painting is saved where it lives; other files go where that kind went last.
  if (purpose == FilePurpose::kSavePainting && beside) return *beside;
  if (const auto remembered = memory.folder_for(purpose)) return *remembered;
  if (beside) return *beside;
  // The folder Impasto was started in (the window never changes it), else home.
  if (const fs::path started = fs::current_path(error); !error && fs::is_directory(started, error))
    return started;
  return home_folder();
}

}  // namespace impasto::app::window
