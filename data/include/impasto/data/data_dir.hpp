#pragma once
// The data folder is found in one place for every module: impasto::files::data_dir()
// ($IMPASTO_DATA_DIR, then <exe>/../share/impasto, then the source tree's data/).
#include "impasto/files/data_dir.hpp"

namespace impasto::data {

using files::data_dir;

}  // namespace impasto::data
