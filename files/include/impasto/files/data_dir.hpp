#pragma once
// The one place that says where Impasto's bundled data (brushes, pigments, spectra, flakes,
// cracks, tablets, strokes) is found, for every module and for the installed program.
#include <filesystem>
#include <string>

namespace impasto::files {

// Where to look, in order. An empty path is skipped.
struct DataDirCandidates {
  std::string environment;                // $IMPASTO_DATA_DIR: when set, it must be a folder
  std::filesystem::path executable;       // the running program: <exe>/../share/impasto
  std::filesystem::path source_data_dir;  // the source tree's data/, for a program that
  std::filesystem::path build_dir;        // lies in this build folder (an installed copy
                                          // never reads the source tree, which may be gone
                                          // or of another version)
};

// The first candidate that is a folder holding data. Throws std::runtime_error when
// $IMPASTO_DATA_DIR names no folder, or when no candidate exists (the message lists them).
std::filesystem::path find_data_dir(const DataDirCandidates& candidates);

// find_data_dir with $IMPASTO_DATA_DIR, this process's executable and the source and build
// trees of this build. The answer is looked up again at each call (the variable may change).
std::filesystem::path data_dir();

// <folder holding the executable>/../share/impasto: the installed layout, wherever the
// prefix was moved to.
std::filesystem::path installed_data_dir(const std::filesystem::path& executable);

}  // namespace impasto::files
