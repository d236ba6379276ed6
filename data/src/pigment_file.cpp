#include <cctype>
#include <stdexcept>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectral_csv.hpp"
#include "impasto/files/confined_path.hpp"
#include "impasto/files/data_dir.hpp"
#include "impasto/files/message_text.hpp"

namespace impasto::data {
namespace {

// The library a pigment file's '# flakes:' may reach into: its own folder, except for the
// bundled pigments, whose flakes live beside them in the data folder (data/flakes). A user's
// or a --pigments folder never reaches the folder above it (its owner's home, say).
std::filesystem::path flake_library(const std::filesystem::path& folder) {
  std::error_code error;
  const std::filesystem::path data = files::data_dir();
  if (std::filesystem::equivalent(folder, data / "pigments", error)) return data;
  return folder;
}

// The '# flakes:' file of a pigment, relative to the pigment file's folder and inside its
// library (above): no absolute path, no climbing out, no symlink out. It must exist (the
// renderer reads it, knowing the flake format).
std::filesystem::path flake_file(const std::map<std::string, std::string>& metadata,
                                 const std::filesystem::path& pigment_file) {
  const auto entry = metadata.find("flakes");
  if (entry == metadata.end()) return {};
  const std::string where = pigment_file.string() + ": field 'flakes': ";
  if (entry->second.empty()) throw std::runtime_error(where + "names no file");
  const std::filesystem::path folder = std::filesystem::absolute(pigment_file).parent_path();
  const std::filesystem::path file = files::confined_path(
      flake_library(folder), folder, entry->second, pigment_file.string() + ": field 'flakes'");
  if (!std::filesystem::is_regular_file(file)) {
    throw std::runtime_error(where + files::excerpt(file.string()) + " is not a file");
  }
  return std::filesystem::absolute(file).lexically_normal();
}

}  // namespace

Pigment read_pigment_file(const std::filesystem::path& path) {
  SpectralTable table = read_spectral_csv(path);
  const std::string where = path.string() + ": ";
  if (table.quantity != SpectralQuantity::kubelka_munk) {
    throw std::runtime_error(where + "a pigment file needs '# quantity: kubelka_munk'");
  }
  const auto name = table.metadata.find("name");
  if (name == table.metadata.end() || name->second.empty()) {
    throw std::runtime_error(where + "a pigment file needs a '# name: ...' line");
  }
  const Spectrum* K = table.find("K");
  const Spectrum* S = table.find("S");
  if (K == nullptr || S == nullptr) {
    throw std::runtime_error(where + "a pigment file needs columns K and S");
  }
  Pigment pigment{name->second, *K, *S, std::move(table.metadata)};
  pigment.K.name = std::string("K");
  pigment.S.name = std::string("S");
  pigment.flakes = flake_file(pigment.metadata, path);
  return pigment;
}

void write_pigment_file(const std::filesystem::path& path, const Pigment& pigment) {
  auto metadata = pigment.metadata;
  metadata["name"] = pigment.name;
  Spectrum K{"K", pigment.K.wavelengths_nm, pigment.K.values};
  Spectrum S = pigment.S.resampled(K.wavelengths_nm);
  S.name = std::string("S");
  write_spectral_csv(path, make_spectral_table(SpectralQuantity::kubelka_munk,
                                               {std::move(K), std::move(S)}, std::move(metadata)));
}

std::string pigment_file_name(std::string_view pigment_name) {
  std::string out;
  for (const char c : pigment_name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty()) out = "pigment";
  return out + ".csv";
}

}  // namespace impasto::data
