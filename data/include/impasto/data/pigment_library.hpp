#pragma once
// The layered pigment library (docs/pigments.md): the bundled database (read-only), the
// user's folder ($XDG_DATA_HOME/impasto/pigments, default ~/.local/share/impasto/pigments)
// and any folders given with --pigments, in that order. A later layer overrides a name (a
// note says so); a bad file, or a second file with a name already in its own folder, is
// reported (file, line, field) and skipped, and the rest loads.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "impasto/data/pigments.hpp"

namespace impasto::data {

struct PigmentLayer {
  std::string label;  // "bundled", "add-on", "user", "--pigments"
  std::filesystem::path folder;
  bool writable = false;  // the user layer; the bundled one never
  bool required = false;  // a missing folder is an error (else: an empty layer)
};

// One folder read file by file: every file that loads, and one message per file that does not
// ("FILE:LINE: ..." for CSV errors, "FILE: field 'X': ..." for pigment fields).
struct PigmentFolderScan {
  struct Loaded {
    Pigment pigment;
    std::filesystem::path file;
  };
  std::vector<Loaded> pigments;       // sorted by file name; names unique within the folder
  std::vector<std::string> problems;  // bad files and duplicate names, all of them
};
PigmentFolderScan scan_pigment_folder(const std::filesystem::path& folder);

struct LibraryPigment {
  std::string layer;  // the label of the layer it comes from
  std::filesystem::path file;
};

class PigmentLibrary {
 public:
  // Layers in order; later ones override earlier ones by exact name. Throws when a required
  // layer's folder is missing or when no pigment loads at all.
  static PigmentLibrary load(const std::vector<PigmentLayer>& layers);

  const PigmentDatabase& database() const { return *database_; }
  // Where each of database().all() comes from (same order).
  const std::vector<LibraryPigment>& origins() const { return origins_; }
  const LibraryPigment* origin(std::string_view name) const;
  // "user: 'My Red' (FILE) overrides the bundled one (FILE)".
  const std::vector<std::string>& notes() const { return notes_; }
  // Files skipped, with why.
  const std::vector<std::string>& problems() const { return problems_; }
  const std::vector<PigmentLayer>& layers() const { return layers_; }
  // The user layer's folder (writable), or empty.
  std::filesystem::path user_folder() const;

 private:
  std::shared_ptr<const PigmentDatabase> database_;
  std::vector<LibraryPigment> origins_;
  std::vector<std::string> notes_, problems_;
  std::vector<PigmentLayer> layers_;
};

// $XDG_DATA_HOME/impasto/pigments, or ~/.local/share/impasto/pigments; empty with neither.
std::filesystem::path user_pigment_folder();
// Pigment sets installed apart from the program, each a folder under data_dir()/pigment-addons
// (a separate package, such as impasto-pigments-okumura, installs one there).
inline constexpr const char* kPigmentAddonsFolder = "pigment-addons";
// Those folders, sorted; none when the folder is absent.
std::vector<std::filesystem::path> pigment_addon_folders();
// For a pigment the library lacks, how to get it, as the end of a message (": ..."): the
// optional add-on that holds it (the 27 Golden acrylics of earlier versions' default set),
// else a user pigment folder or --pigments DIR.
std::string where_to_get_pigment(std::string_view name);
// bundled (data_dir()/pigments), each add-on folder, user, then each extra folder.
std::vector<PigmentLayer> standard_pigment_layers(
    const std::vector<std::filesystem::path>& extra_folders);

// The process's library: the standard layers with the folders added here (by --pigments,
// before anything reads pigments). PigmentDatabase::defaults() is its database. The first
// load prints its notes and problems to stderr once.
void add_pigment_folder(const std::filesystem::path& folder);
const PigmentLibrary& active_pigment_library();
// Reads the layers again (after the editor or a command changed the user layer). References
// from earlier loads stay valid (old libraries are kept) but no longer change.
const PigmentLibrary& reload_active_pigment_library();

}  // namespace impasto::data
