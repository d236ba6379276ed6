#include "impasto/data/pigment_text.hpp"

#include <stdexcept>

#include "impasto/data/spectral_csv.hpp"

namespace impasto::data {

std::string format_pigment_text(const Pigment& pigment) {
  auto metadata = pigment.metadata;
  metadata["name"] = pigment.name;
  Spectrum K{"K", pigment.K.wavelengths_nm, pigment.K.values};
  Spectrum S = pigment.S.resampled(K.wavelengths_nm);
  S.name = std::string("S");
  return format_spectral_csv(make_spectral_table(
      SpectralQuantity::kubelka_munk, {std::move(K), std::move(S)}, std::move(metadata)));
}

Pigment parse_pigment_text(std::string_view text, const std::string& source) {
  SpectralTable table = parse_spectral_csv(text, source);
  const std::string where = source + ": ";
  if (table.quantity != SpectralQuantity::kubelka_munk)
    throw std::runtime_error(where + "a pigment needs '# quantity: kubelka_munk'");
  const auto name = table.metadata.find("name");
  if (name == table.metadata.end() || name->second.empty())
    throw std::runtime_error(where + "a pigment needs a '# name: ...' line");
  const Spectrum* K = table.find("K");
  const Spectrum* S = table.find("S");
  if (K == nullptr || S == nullptr)
    throw std::runtime_error(where + "a pigment needs columns K and S");
  Pigment pigment{name->second, *K, *S, std::move(table.metadata)};
  pigment.K.name = std::string("K");
  pigment.S.name = std::string("S");
  return pigment;
}

}  // namespace impasto::data
