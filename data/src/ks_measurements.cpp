// The measurements CSV read by `impasto pigments fit` (layout in docs/pigments.md).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "impasto/data/ks_fit.hpp"
#include "impasto/data/spectral_csv.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"

namespace impasto::data {
namespace {

constexpr std::string_view kMixPrefix = "mix ";

using util::trim;

std::optional<double> parse_double(std::string_view text) {
  text = trim(text);
  double value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// "Pigment A=0.25; Pigment B=0.75" → {(Pigment A, 0.25), (Pigment B, 0.75)}.
std::vector<std::pair<std::string, double>> parse_mix(std::string_view text,
                                                      const std::string& where) {
  std::vector<std::pair<std::string, double>> parts;
  while (!text.empty()) {
    const auto semicolon = text.find(';');
    const std::string_view part = trim(text.substr(0, semicolon));
    text = semicolon == std::string_view::npos ? std::string_view{} : text.substr(semicolon + 1);
    if (part.empty()) continue;
    const auto equals = part.rfind('=');
    const std::string name(equals == std::string_view::npos ? std::string_view{}
                                                            : trim(part.substr(0, equals)));
    const auto amount =
        equals == std::string_view::npos ? std::nullopt : parse_double(part.substr(equals + 1));
    if (name.empty() || !amount || *amount < 0) {
      throw std::runtime_error(where + "expected 'Pigment=concentration' (>= 0), got " +
                               files::excerpt(part));
    }
    parts.emplace_back(name, *amount);
  }
  if (parts.empty()) throw std::runtime_error(where + "empty mix");
  return parts;
}

}  // namespace

KsFitProblem read_ks_measurements(const std::filesystem::path& path) {
  const SpectralTable table = read_spectral_csv(path);
  const std::string file = path.string();
  auto at_line = [&](const std::string& key) {
    return file + ":" + std::to_string(table.metadata_lines.at(key)) + ": ";
  };
  if (table.quantity != SpectralQuantity::reflectance) {
    throw std::runtime_error(file + ": measurements need '# quantity: reflectance'");
  }

  KsFitProblem problem;
  const auto reference = table.metadata.find("reference");
  if (reference == table.metadata.end() || reference->second.empty()) {
    throw std::runtime_error(file + ": no '# reference: PIGMENT' line (the pigment with S = 1)");
  }
  problem.reference_pigment = reference->second;

  if (const auto found = table.metadata.find("saunderson"); found != table.metadata.end()) {
    std::string text = found->second;
    for (char& c : text) c = c == ',' ? ' ' : c;
    const auto space = trim(text).find(' ');
    const std::string_view both = trim(text);
    const auto k1 =
        space == std::string_view::npos ? std::nullopt : parse_double(both.substr(0, space));
    const auto k2 =
        space == std::string_view::npos ? std::nullopt : parse_double(both.substr(space));
    if (!k1 || !k2 || !saunderson_coefficient_valid(*k1) || !saunderson_coefficient_valid(*k2)) {
      throw std::runtime_error(at_line("saunderson") + "expected '# saunderson: K1 K2' with both " +
                               kSaundersonCoefficientRange);
    }
    problem.saunderson = Saunderson{*k1, *k2};
  }
  if (const auto found = table.metadata.find("surface_seen"); found != table.metadata.end()) {
    const auto seen = parse_double(trim(found->second));
    if (!problem.saunderson || !seen || !(*seen >= 0.0 && *seen <= 1.0)) {
      throw std::runtime_error(at_line("surface_seen") +
                               "expected '# surface_seen: SHARE' in [0, 1] (the share of the "
                               "surface reflection k1 the instrument read), after a "
                               "'# saunderson: K1 K2' line");
    }
    problem.saunderson->surface_seen = *seen;
  }

  // Every "mix" line names a column; pigments are numbered in order of first mention.
  std::vector<std::vector<std::pair<std::string, double>>> mixes(table.columns.size());
  std::vector<bool> has_mix(table.columns.size(), false);
  for (const auto& [key, value] : table.metadata) {
    if (!key.starts_with(kMixPrefix)) continue;
    const std::string column(trim(std::string_view(key).substr(kMixPrefix.size())));
    std::size_t c = 0;
    while (c < table.columns.size() && table.columns[c].name != column) ++c;
    if (c == table.columns.size()) {
      throw std::runtime_error(at_line(key) + "'mix " + column + "' names no column of the table");
    }
    mixes[c] = parse_mix(value, at_line(key));
    has_mix[c] = true;
  }
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (!has_mix[c]) {
      throw std::runtime_error(file + ": column '" + table.columns[c].name + "' has no '# mix " +
                               table.columns[c].name + ": Pigment=amount; ...' line");
    }
  }
  // Metadata are sorted by key; number pigments by column order instead, for stable output.
  for (const auto& mix : mixes) {
    for (const auto& [name, amount] : mix) {
      if (std::find(problem.pigment_names.begin(), problem.pigment_names.end(), name) ==
          problem.pigment_names.end()) {
        problem.pigment_names.push_back(name);
      }
    }
  }
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    KsSample sample{table.columns[c].name, table.columns[c],
                    std::vector<double>(problem.pigment_names.size(), 0.0)};
    for (const auto& [name, amount] : mixes[c]) {
      const auto j = static_cast<std::size_t>(
          std::find(problem.pigment_names.begin(), problem.pigment_names.end(), name) -
          problem.pigment_names.begin());
      sample.concentrations[j] += amount;
    }
    problem.samples.push_back(std::move(sample));
  }
  problem.grid_nm = table.wavelengths_nm;
  return problem;
}

}  // namespace impasto::data
