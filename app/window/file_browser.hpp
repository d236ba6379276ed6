#pragma once
// The window's file dialog, in Dear ImGui: a folder's files of the purpose's type (folders
// to go into, the parent, a typed path), places on the left (home, the painting's folder, the
// last folders used, recent files), a file name proposed for saving and exporting, and a
// confirmation before a file is replaced. The last folder of each purpose is remembered
// across sessions (file_browser_model.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "window/file_browser_model.hpp"

namespace impasto::app::window {

struct FileBrowserRequest {
  FilePurpose purpose = FilePurpose::kOpenPainting;
  std::string title;         // "Save painting as"
  std::string accept_label;  // "Save"
  // The painting's file (none: untitled), for the proposed name and the starting folder.
  std::optional<std::filesystem::path> painting;
  std::vector<std::filesystem::path> recent_files;  // newest first (recent_files.hpp)
};

struct FileBrowserResult {
  enum Kind { kNone, kChosen, kCancelled } kind = kNone;
  FilePurpose purpose = FilePurpose::kOpenPainting;
  std::filesystem::path file;  // absolute, with the filter's extension for a save
};

class FileBrowser {
 public:
  // `folder_memory`: where the last folders are kept (none: not remembered).
  explicit FileBrowser(std::filesystem::path folder_memory);

  // Shows the dialog from the next draw().
  void open(FileBrowserRequest request);
  bool is_open() const { return open_ || open_requested_; }
  // Draws the dialog while it is open (inside an ImGui frame, at the top of the ID stack);
  // says once when a file was chosen or the dialog cancelled.
  FileBrowserResult draw();

  // The folder and name as they stand (for tests and the status of a half-filled dialog).
  const std::filesystem::path& folder() const { return folder_; }
  const std::string& name() const { return name_; }

 private:
  void navigate(const std::filesystem::path& folder);
  void refresh();
  // The file name field's or a double-clicked entry's file: chosen, a folder gone into, or
  // an error shown; a file to be replaced asks first.
  FileBrowserResult try_accept(const std::string& typed);
  FileBrowserResult choose(const std::filesystem::path& file);
  void draw_places();
  bool draw_listing(std::string* accepted);

  FolderMemory memory_;
  FileBrowserRequest request_;
  std::vector<FileFilter> filters_;
  std::size_t filter_ = 0;
  bool open_requested_ = false, open_ = false, focus_name_ = false;
  std::filesystem::path folder_;
  std::string folder_input_;
  std::string name_;
  std::vector<FolderEntry> entries_;
  bool show_hidden_ = false;
  std::string error_;
  std::filesystem::path replace_;  // set while asking whether to replace it
};

}  // namespace impasto::app::window
