// Writing spectral CSV files (docs/spectral-csv.md) and assembling tables to write.
#include <csv.h>

#include <stdexcept>

#include "impasto/data/spectral_csv.hpp"
#include "impasto/files/atomic_file.hpp"
#include "spectral_text.hpp"

namespace impasto::data {

using detail::format_number;
using detail::trim;

std::string format_spectral_csv(const SpectralTable& table) {
  std::string out;
  if (table.quantity != SpectralQuantity::unspecified) {
    out += "# quantity: " + std::string(to_string(table.quantity)) + "\n";
  }
  for (const auto& [key, value] : table.metadata) {
    if (key == "quantity") continue;
    if (trim(key).empty() || key.find_first_of(":\n\r") != std::string::npos ||
        value.find_first_of("\n\r") != std::string::npos) {
      throw std::runtime_error("metadata '" + key + "' cannot be written as '# key: value'");
    }
    out += "# " + key + ": " + value + "\n";
  }
  out += "wavelength_nm";
  for (const auto& column : table.columns) {
    out += ',';
    if (column.name.find_first_of(",\"#") == std::string::npos) {
      out += column.name;
    } else {  // libcsv quotes the name and doubles its quotes
      std::string quoted(2 * column.name.size() + 2, '\0');
      quoted.resize(
          csv_write(quoted.data(), quoted.size(), column.name.data(), column.name.size()));
      out += quoted;
    }
  }
  out += '\n';
  for (std::size_t i = 0; i < table.wavelengths_nm.size(); ++i) {
    out += format_number(table.wavelengths_nm[i]);
    for (const auto& column : table.columns) out += ',' + format_number(column.values.at(i));
    out += '\n';
  }
  return out;
}

void write_spectral_csv(const std::filesystem::path& path, const SpectralTable& table) {
  files::write_file_atomically(path, format_spectral_csv(table));
}

SpectralTable make_spectral_table(SpectralQuantity quantity, std::vector<Spectrum> columns,
                                  std::map<std::string, std::string> metadata) {
  if (columns.empty()) throw std::runtime_error("a spectral table needs at least one column");
  SpectralTable table{quantity, std::move(metadata), columns.front().wavelengths_nm, {}, {}};
  for (auto& column : columns) {
    if (column.wavelengths_nm != table.wavelengths_nm) {
      throw std::runtime_error("column '" + column.name +
                               "' is not on the table's wavelength grid");
    }
    if (column.values.size() != column.wavelengths_nm.size()) {
      throw std::runtime_error("column '" + column.name + "' has " +
                               std::to_string(column.values.size()) + " values for " +
                               std::to_string(column.wavelengths_nm.size()) + " wavelengths");
    }
  }
  table.columns = std::move(columns);
  return table;
}

}  // namespace impasto::data
