#pragma once
// Spectral CSV files (docs/spectral-csv.md): "# key: value" metadata lines, a header
// "wavelength_nm,NAME1,NAME2,..." and one row per wavelength (nm), one column per sample.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/data/spectrum.hpp"

namespace impasto::data {

// What the values mean (the `# quantity:` line); it sets the range the loader accepts.
// The largest Kubelka-Munk K or S a file may hold (white's S is 1; real paints stay below
// 1e3): beyond it K (K + 2S) leaves the float range the renderer computes in, so a value no
// render can use is refused where it is read or entered, not when a render meets it.
inline constexpr double kMaxKubelkaMunk = 1e6;

enum class SpectralQuantity {
  unspecified,     // no quantity line: values need only be finite
  reflectance,     // 0..1
  transmittance,   // 0..1
  spectral_power,  // >= 0, relative or absolute (see `# units:`)
  cmf,             // colour-matching functions, >= 0
  kubelka_munk,    // K and S coefficients, >= 0
};

std::string_view to_string(SpectralQuantity quantity);
// Throws std::runtime_error listing the known quantities.
SpectralQuantity parse_spectral_quantity(std::string_view text);

// The contents of one spectral CSV file.
struct SpectralTable {
  SpectralQuantity quantity = SpectralQuantity::unspecified;
  std::map<std::string, std::string> metadata;  // every "# key: value" line, quantity included
  std::vector<double> wavelengths_nm;           // strictly increasing
  std::vector<Spectrum> columns;                // named by the header; same wavelengths each
  std::map<std::string, std::size_t> metadata_lines;  // line number of each metadata key

  const Spectrum* find(std::string_view column_name) const;
  // Throws std::runtime_error naming the missing column and the ones present.
  const Spectrum& column(std::string_view column_name) const;
};

// Reads and validates a spectral CSV. Errors are std::runtime_error with "file:line:column:"
// (column counts CSV cells from 1) and what is wrong.
SpectralTable read_spectral_csv(const std::filesystem::path& path);
// The same from text; source_name stands for the file name in error messages.
SpectralTable parse_spectral_csv(std::string_view text, const std::string& source_name);

// Writes the table in the same format (shortest round-trip decimal numbers). The quantity
// line comes from table.quantity; metadata["quantity"] is ignored.
void write_spectral_csv(const std::filesystem::path& path, const SpectralTable& table);
std::string format_spectral_csv(const SpectralTable& table);

// A table of spectra that share one wavelength grid; throws if their grids differ.
SpectralTable make_spectral_table(SpectralQuantity quantity, std::vector<Spectrum> columns,
                                  std::map<std::string, std::string> metadata = {});

}  // namespace impasto::data
