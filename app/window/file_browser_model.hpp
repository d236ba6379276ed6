#pragma once
// What the file browser (file_browser.hpp) shows and decides, without ImGui: the kinds of
// file each purpose takes, a folder's listing, typed paths, the name a dialog proposes, and
// the last folder used for each purpose, kept across sessions in the user's config folder.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impasto::app::window {

// What a file is chosen for; each has its own filters and remembered folder.
enum class FilePurpose { kOpenPainting, kSavePainting, kExportImage, kOpenStrokes, kOpenReference };

// "Painting (*.impasto)" and the extensions it takes, lower case with the dot.
struct FileFilter {
  std::string label;
  std::vector<std::string> extensions;
  // Names ending so are not this kind though their extension is (a painting's palette board,
  // "x.palette.impasto", is kept beside it and opened with it).
  std::vector<std::string> excluded_endings = {};
};

// The purpose's filters, the preferred first; every purpose ends with "All files" (no
// extensions) except those that write, where the file's type must be one the program writes.
std::vector<FileFilter> filters_for(FilePurpose purpose);
// Whether a save dialog (asks before replacing a file) or an open dialog.
bool writes_file(FilePurpose purpose);
// The key the purpose's folder is remembered under: open and save share "painting".
std::string folder_key(FilePurpose purpose);

// Whether `file`'s extension (case-insensitive) is one of the filter's; a filter without
// extensions takes every file.
bool filter_matches(const FileFilter& filter, const std::filesystem::path& file);

// A typed name made a file of the filter's type: kept when its extension is the filter's,
// the extension replaced when it is one of Impasto's other kinds (.impasto, .png, .exr,
// .strokes: a name carried over from another dialog), else the filter's first appended
// ("v1.2" -> "v1.2.png"). A filter without extensions keeps the name.
std::filesystem::path with_filter_extension(const std::filesystem::path& name,
                                            const FileFilter& filter);

// A folder's entries: folders first, then files the filter takes, each sorted by name
// (case-insensitive); hidden ones (".name") only when asked. A folder that cannot be read
// gives what was read and sets *error to why, naming the folder.
struct FolderEntry {
  std::string name;
  bool is_folder = false;
  std::uintmax_t size_bytes = 0;
};
std::vector<FolderEntry> list_folder(const std::filesystem::path& folder, const FileFilter& filter,
                                     bool show_hidden, std::string* error);

// A typed path read against the folder shown: "~" and "~/x" are the home folder, a relative
// path is under `folder`; "." and ".." parts are resolved (lexically).
std::filesystem::path resolve_typed_path(const std::filesystem::path& folder,
                                         const std::string& typed);

// The file name a dialog proposes: the painting's own name to save it ("Untitled.impasto"
// for a new one), its stem with the image extension to export ("Untitled.png"), and none to
// open.
std::string proposed_file_name(FilePurpose purpose,
                               const std::optional<std::filesystem::path>& painting);

// The home folder ($HOME), or the current folder where it is unset.
std::filesystem::path home_folder();

// The last folder of each purpose (folder_key), kept in
// <config>/impasto/folders.txt as "key<TAB>folder" lines.
class FolderMemory {
 public:
  // Reads the list from `file` (missing or unreadable: nothing remembered).
  explicit FolderMemory(std::filesystem::path file);
  // The remembered folder while it still exists.
  std::optional<std::filesystem::path> folder_for(FilePurpose purpose) const;
  // Remembers `folder` for the purpose and writes the list; a read-only config folder keeps
  // the old list (errors are ignored: remembering is a convenience).
  void remember(FilePurpose purpose, const std::filesystem::path& folder);
  // Every remembered folder that still exists, once each.
  std::vector<std::filesystem::path> folders() const;

 private:
  std::filesystem::path file_;
  std::map<std::string, std::filesystem::path> folders_;
};

// Where a dialog starts: Save as in the painting's folder; otherwise the purpose's remembered
// folder, else the painting's folder, else the folder Impasto was started in, else home.
std::filesystem::path starting_folder(const FolderMemory& memory, FilePurpose purpose,
                                      const std::optional<std::filesystem::path>& painting);

}  // namespace impasto::app::window
