#include "impasto/data/lights.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "impasto/data/spectral_csv.hpp"

namespace impasto::data {
namespace {

// Second radiation constant c2 = h·c/k_B (CODATA 2018), in nm·K.
constexpr double kSecondRadiationConstant_nmK = 1.438776877e7;
constexpr double kNormalisation_nm = 560.0;
constexpr double kMinimum_K = 100.0;

// log(e^a − 1) without overflow for large a.
double log_expm1(double a) {
  return a > 30.0 ? a + std::log1p(-std::exp(-a)) : std::log(std::expm1(a));
}

// log of Planck's spectral radiance up to a constant: −5·log λ − log(e^(c2/λT) − 1).
double log_planck(double nm, double kelvin) {
  return -5.0 * std::log(nm) - log_expm1(kSecondRadiationConstant_nmK / (nm * kelvin));
}

Spectrum light_from_csv(const std::filesystem::path& path) {
  const SpectralTable table = read_spectral_csv(path);
  if (table.quantity != SpectralQuantity::spectral_power &&
      table.quantity != SpectralQuantity::unspecified) {
    throw std::runtime_error(path.string() + ": a light needs '# quantity: spectral_power', not " +
                             std::string(to_string(table.quantity)));
  }
  if (table.columns.size() != 1) {
    throw std::runtime_error(path.string() + ": a light CSV has exactly one value column, found " +
                             std::to_string(table.columns.size()));
  }
  for (std::size_t i = 0; i < table.wavelengths_nm.size(); ++i) {
    if (table.columns.front().values[i] < 0.0) {
      throw std::runtime_error(path.string() + ": negative power at " +
                               std::to_string(table.wavelengths_nm[i]) + " nm");
    }
  }
  return table.columns.front();
}

}  // namespace

Spectrum blackbody(double kelvin, const std::vector<double>& grid_nm) {
  // Far below 100 K the ratio to the power at 560 nm overflows a double in the infrared.
  if (!std::isfinite(kelvin) || kelvin < kMinimum_K) {
    throw std::runtime_error("blackbody: temperature must be at least 100 K, got " +
                             std::to_string(kelvin) + " K");
  }
  Spectrum spd{"blackbody:" + std::to_string(static_cast<long long>(std::llround(kelvin))), grid_nm,
               std::vector<double>(grid_nm.size())};
  const double log_reference = log_planck(kNormalisation_nm, kelvin);
  for (std::size_t i = 0; i < grid_nm.size(); ++i) {
    const double nm = grid_nm[i];
    if (!std::isfinite(nm) || nm <= 0.0) {
      throw std::runtime_error("blackbody: wavelength " + std::to_string(nm) +
                               " nm is not positive");
    }
    spd.values[i] = std::exp(log_planck(nm, kelvin) - log_reference);
  }
  return spd;
}

Spectrum light_from_spec(std::string_view spec) {
  constexpr std::string_view kBlackbody = "blackbody:";
  if (spec.starts_with(kBlackbody)) {
    const std::string_view number = spec.substr(kBlackbody.size());
    double kelvin = 0.0;
    const auto result = std::from_chars(number.data(), number.data() + number.size(), kelvin);
    if (result.ec != std::errc() || result.ptr != number.data() + number.size() ||
        !std::isfinite(kelvin) || kelvin < kMinimum_K) {
      throw std::runtime_error("light '" + std::string(spec) +
                               "': expected blackbody:KELVIN with KELVIN >= 100");
    }
    return blackbody(kelvin, wavelength_grid(300.0, 830.0, 1.0));
  }
  // Illuminant names win over files of the same name in the working folder.
  const auto names = illuminant_names();
  for (const auto& name : names) {
    if (name.size() == spec.size() &&
        std::equal(name.begin(), name.end(), spec.begin(), [](char a, char b) {
          return std::toupper(static_cast<unsigned char>(a)) ==
                 std::toupper(static_cast<unsigned char>(b));
        })) {
      return cie_illuminant(name);
    }
  }
  const std::filesystem::path path(spec);
  if (std::filesystem::exists(path) || path.extension() == ".csv") return light_from_csv(path);
  std::string known;
  for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
  throw std::runtime_error("unknown light '" + std::string(spec) +
                           "': expected a CIE illuminant (" + known +
                           "), blackbody:KELVIN, or the path of a light CSV");
}

}  // namespace impasto::data
