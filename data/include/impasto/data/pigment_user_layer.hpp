#pragma once
// Changes to a writable pigment folder (the user layer): every file written atomically
// (write_pigment_file goes through files::write_file_atomically), with its provenance in the
// file ('# modified:', '# fitted_from:'). The bundled layer is never written.
#include <filesystem>
#include <string>

#include "impasto/data/pigments.hpp"

namespace impasto::data {

// Today's date and time in UTC, ISO 8601 ("2026-12-01T18:40:00Z"), for '# modified:'.
std::string utc_timestamp();

// Writes `pigment` as FOLDER/pigment_file_name(name). Refuses (std::runtime_error) to replace
// an existing file unless `overwrite`, or a file of the folder holding another pigment's
// name. A flake pigment's *.flake file (and the n,k table it names) is copied beside it and
// the '# flakes:' line made to name the copy. Returns the file written.
std::filesystem::path save_pigment_to_folder(const std::filesystem::path& folder, Pigment pigment,
                                             bool overwrite);
// Reads FILE (a pigment CSV) and saves it into folder: numbers and metadata unchanged.
std::filesystem::path import_pigment_file(const std::filesystem::path& folder,
                                          const std::filesystem::path& file, bool overwrite);
// The file of `folder` whose pigment is named `name` (exact, then case-insensitive); throws
// naming the folder when none is.
std::filesystem::path pigment_file_in_folder(const std::filesystem::path& folder,
                                             const std::string& name);
// Renames a pigment of the folder (new file name, '# modified:'); refuses a name in use.
std::filesystem::path rename_pigment_in_folder(const std::filesystem::path& folder,
                                               const std::string& name,
                                               const std::string& new_name);
// Removes a pigment's file from the folder (its flake file stays: others may share it).
std::filesystem::path remove_pigment_from_folder(const std::filesystem::path& folder,
                                                 const std::string& name);

}  // namespace impasto::data
