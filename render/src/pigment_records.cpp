#include "impasto/render/pigment_records.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "impasto/data/pigment_text.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/cache_dir.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/fnv1a.hpp"
#include "impasto/util/text.hpp"

namespace impasto::render {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kFileMark = "#impasto-record-file ";
constexpr const char* kGroundPigment = "White";  // as spectral_palette.cpp
// The carried flake paints kept in the cache, the most recently used: a painting's few, many
// times over (each record is a folder of a few kB).
constexpr std::size_t kKeptCarriedPigments = 256;

// "key = value" of a flake paint file, or empty.
std::string flake_field(const std::string& text, const std::string& key) {
  return util::key_value_field(text, key);
}

// A file name a record may use: no folder part, nothing hidden.
bool plain_file_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find('/') == std::string::npos &&
         name.size() < 256;
}

fs::path cache_root() {
  return files::cache_dir("carried-flakes");
}

}  // namespace

std::string pigment_record(const data::Pigment& pigment) {
  data::Pigment copy = pigment;
  if (pigment.flakes.empty()) {
    copy.metadata.erase("flakes");
    return data::format_pigment_text(copy);
  }
  const std::string flake_name = pigment.flakes.filename().string();
  copy.metadata["flakes"] = flake_name;
  std::string record = data::format_pigment_text(copy);
  const std::string flake_text = files::read_whole_file(pigment.flakes, "flake paint");
  record += std::string(kFileMark) + flake_name + "\n" + flake_text;
  if (!record.empty() && record.back() != '\n') record += '\n';
  if (const std::string table = flake_field(flake_text, "nk_table"); !table.empty()) {
    if (!plain_file_name(table))
      throw std::runtime_error(pigment.flakes.string() + ": field 'nk_table': " +
                               files::excerpt(table) + " is not a file beside it");
    record += std::string(kFileMark) + table + "\n" +
              files::read_whole_file(pigment.flakes.parent_path() / table, "n,k table");
  }
  return record;
}

data::Pigment pigment_from_record(const std::string& record, const std::string& where) {
  // Split into the pigment text and the named files after it.
  std::vector<std::pair<std::string, std::string>> files;
  std::string text;
  std::size_t start = 0;
  std::string* into = &text;
  while (start < record.size()) {
    std::size_t end = record.find('\n', start);
    end = end == std::string::npos ? record.size() : end + 1;
    const std::string_view line(record.data() + start, end - start);
    start = end;
    if (line.substr(0, kFileMark.size()) == kFileMark) {
      std::string name(line.substr(kFileMark.size()));
      while (!name.empty() && (name.back() == '\n' || name.back() == '\r')) name.pop_back();
      if (!plain_file_name(name))
        throw std::runtime_error(where + ": a carried file is named " + files::excerpt(name));
      files.emplace_back(name, std::string());
      into = &files.back().second;
      continue;
    }
    into->append(line);
  }
  data::Pigment pigment = data::parse_pigment_text(text, where);
  const auto flakes = pigment.metadata.find("flakes");
  if (flakes == pigment.metadata.end()) return pigment;
  // A record carries its flake file and that file's n,k table: nothing else is written.
  const auto carried = [&](const std::string& name) -> const std::string* {
    for (const auto& file : files)
      if (file.first == name) return &file.second;
    return nullptr;
  };
  const std::string* flake_text = carried(flakes->second);
  if (flake_text == nullptr)
    throw std::runtime_error(where + ": pigment " + files::excerpt(pigment.name) +
                             " names flake file " + files::excerpt(flakes->second) +
                             " but does not carry it");
  const std::string table = flake_field(*flake_text, "nk_table");
  for (const auto& file : files) {
    if (file.first != flakes->second && file.first != table)
      throw std::runtime_error(where + ": carries a file its pigment does not need, " +
                               files::excerpt(file.first));
  }
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(util::fnv1a(record)));
  const fs::path root = cache_root();
  const fs::path folder = root / hash;
  fs::create_directory(folder);
  for (const auto& [name, contents] : files) {
    const fs::path path = folder / name;
    std::error_code error;
    if (fs::is_regular_file(fs::symlink_status(path, error)) &&
        fs::file_size(path, error) == contents.size() &&
        files::read_whole_file(path, "carried flake file") == contents)
      continue;
    files::write_file_atomically(path, contents);
  }
  files::touch_cache_entry(folder);
  files::trim_cache(root, kKeptCarriedPigments);
  pigment.flakes = folder / flakes->second;
  return pigment;
}

std::shared_ptr<const std::map<std::string, data::Pigment>> carried_pigments(
    const paintcore::Painting& painting) {
  auto carried = std::make_shared<std::map<std::string, data::Pigment>>();
  for (const auto& [name, record] : painting.pigment_records()) {
    // Keyed by the slot's spelling (the record holds the library's: "pyrrole red" may
    // carry "Red").
    carried->emplace(name,
                     pigment_from_record(record, "the painting's pigment " + files::excerpt(name)));
  }
  return carried;
}

void install_pigment_records() {
  paintcore::Painting::set_pigment_record_source([](const std::string& name) {
    std::map<std::string, std::string> records;
    const auto& db = data::PigmentDatabase::defaults();
    if (const data::Pigment* pigment = db.find(name)) {
      records.emplace(name, pigment_record(*pigment));  // under the slot's own spelling
      if (name != kGroundPigment)
        if (const data::Pigment* white = db.find(kGroundPigment))
          records.emplace(kGroundPigment, pigment_record(*white));
    }
    return records;
  });
}

std::vector<PigmentDrift> pigments_differing_from_library(const paintcore::Painting& painting) {
  std::vector<PigmentDrift> drift;
  const auto& db = data::PigmentDatabase::defaults();
  for (const auto& [name, record] : painting.pigment_records()) {
    const data::Pigment* pigment = db.find(name);
    if (pigment == nullptr) {
      drift.push_back({name, true});
      continue;
    }
    std::string library;
    try {
      library = pigment_record(*pigment);
    } catch (const std::exception&) {
    }
    if (library != record) drift.push_back({name, false});
  }
  return drift;
}

void use_library_pigments(paintcore::Painting& painting, const std::vector<std::string>& names) {
  const auto& db = data::PigmentDatabase::defaults();
  for (const auto& name : names) painting.set_pigment_record(name, pigment_record(db.get(name)));
}

}  // namespace impasto::render
