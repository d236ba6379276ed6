#include <cctype>
#include <stdexcept>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectral_csv.hpp"

namespace impasto::data {

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
