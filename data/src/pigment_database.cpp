#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "impasto/data/data_dir.hpp"
#include "impasto/data/pigment_library.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"

namespace impasto::data {
PigmentDatabase PigmentDatabase::load(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) {
    throw std::runtime_error(dir.string() + ": not a pigment folder");
  }
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // directory order is not deterministic

  PigmentDatabase db;
  std::vector<std::filesystem::path> sources;
  for (const auto& file : files) {
    Pigment pigment = read_pigment_file(file);
    for (std::size_t i = 0; i < db.pigments_.size(); ++i) {
      if (db.pigments_[i].name == pigment.name) {
        throw std::runtime_error(file.string() + ": pigment " + files::excerpt(pigment.name) +
                                 " is also defined in " + sources[i].string());
      }
    }
    db.pigments_.push_back(std::move(pigment));
    sources.push_back(file);
  }
  if (db.pigments_.empty()) throw std::runtime_error(dir.string() + ": no pigment files (*.csv)");
  return db;
}

PigmentDatabase PigmentDatabase::from_pigments(std::vector<Pigment> pigments) {
  PigmentDatabase db;
  db.pigments_ = std::move(pigments);
  return db;
}

const PigmentDatabase& PigmentDatabase::defaults() {
  return active_pigment_library().database();
}

const Pigment* PigmentDatabase::find(std::string_view name) const {
  for (const auto& p : pigments_) {
    if (p.name == name) return &p;
  }
  for (const auto& p : pigments_) {
    if (util::equal_ignoring_case(p.name, name)) return &p;
  }
  return nullptr;
}

const Pigment& PigmentDatabase::get(std::string_view name) const {
  if (const Pigment* p = find(name)) return *p;
  std::string known;
  for (const auto& p : pigments_) known += (known.empty() ? "" : ", ") + p.name;
  throw std::runtime_error("unknown pigment " + files::excerpt(name) + " (known: " + known + ")" +
                           where_to_get_pigment(name));
}

}  // namespace impasto::data
