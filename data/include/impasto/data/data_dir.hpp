#pragma once
#include <filesystem>

namespace impasto::data {

// The folder holding Impasto's data files (spectra, pigments, brushes, strokes).
// Looked up in order: $IMPASTO_DATA_DIR, the source tree's data/ (a build that was not
// installed), the installed share/impasto. Throws std::runtime_error when none exists.
std::filesystem::path data_dir();

}  // namespace impasto::data
