#include "impasto/data/cie.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

#include "impasto/data/data_dir.hpp"
#include "impasto/data/spectral_csv.hpp"

namespace impasto::data {
namespace {

std::filesystem::path illuminant_folder() {
  return data_dir() / "spectra" / "illuminants";
}

// "F2" before "F10": compare the letters, then the number that follows them.
bool natural_less(const std::string& a, const std::string& b) {
  auto split = [](const std::string& s) {
    const auto digits = s.find_first_of("0123456789");
    const std::string letters = s.substr(0, digits);
    const std::string number = digits == std::string::npos ? "" : s.substr(digits);
    return std::make_tuple(letters, number.size(), number);
  };
  return split(a) < split(b);
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

ColorMatchingFunctions load_cie1931_2deg() {
  const auto path = data_dir() / "spectra" / "cie1931_2deg.csv";
  const SpectralTable table = read_spectral_csv(path);
  if (table.quantity != SpectralQuantity::cmf) {
    throw std::runtime_error(path.string() + ": expected '# quantity: cmf'");
  }
  try {
    return {table.column("x_bar"), table.column("y_bar"), table.column("z_bar")};
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace

const ColorMatchingFunctions& cie1931_2deg() {
  static const ColorMatchingFunctions cmf = load_cie1931_2deg();
  return cmf;
}

std::vector<std::string> illuminant_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(illuminant_folder())) {
    if (entry.path().extension() == ".csv") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end(), natural_less);
  return names;
}

Spectrum cie_illuminant(std::string_view name) {
  // Files are read once; later calls copy from the cache.
  static std::mutex mutex;
  static std::map<std::string, Spectrum> cache;
  const std::string key = upper(name);
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(key); found != cache.end()) return found->second;

  const auto names = illuminant_names();
  const auto match = std::find_if(names.begin(), names.end(),
                                  [&](const std::string& n) { return upper(n) == key; });
  if (match == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw std::runtime_error("unknown CIE illuminant '" + std::string(name) + "' (known: " + known +
                             ")");
  }
  const auto path = illuminant_folder() / (*match + ".csv");
  const SpectralTable table = read_spectral_csv(path);
  if (table.quantity != SpectralQuantity::spectral_power || table.columns.size() != 1) {
    throw std::runtime_error(path.string() +
                             ": expected one column with '# quantity: spectral_power'");
  }
  Spectrum spd = table.columns.front();
  spd.name = *match;
  return cache.emplace(key, std::move(spd)).first->second;
}

}  // namespace impasto::data
