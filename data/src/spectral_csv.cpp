// Reading and validating spectral CSV files (docs/spectral-csv.md); lines are split by libcsv.
#include "impasto/data/spectral_csv.hpp"

#include <csv.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "impasto/files/input_file.hpp"
#include "impasto/files/message_text.hpp"
#include "spectral_text.hpp"

namespace impasto::data {
namespace {

using detail::format_number;
using detail::trim;

struct QuantityInfo {
  SpectralQuantity quantity;
  std::string_view name;
  double min, max;
};
constexpr double kInf = HUGE_VAL;
constexpr std::array<QuantityInfo, 6> kQuantities{{
    {SpectralQuantity::unspecified, "unspecified", -kInf, kInf},
    {SpectralQuantity::reflectance, "reflectance", 0.0, 1.0},
    {SpectralQuantity::transmittance, "transmittance", 0.0, 1.0},
    {SpectralQuantity::spectral_power, "spectral_power", 0.0, kInf},
    {SpectralQuantity::cmf, "cmf", 0.0, kInf},
    {SpectralQuantity::kubelka_munk, "kubelka_munk", 0.0, kMaxKubelkaMunk},
}};

const QuantityInfo& info(SpectralQuantity quantity) {
  for (const auto& q : kQuantities) {
    if (q.quantity == quantity) return q;
  }
  throw std::logic_error("unknown SpectralQuantity");
}

// Where a message points: "file:line:column: ".
std::string location(const std::string& source, std::size_t line, std::size_t column = 0) {
  std::string where = source + ':' + std::to_string(line);
  if (column > 0) where.append(":").append(std::to_string(column));
  return where.append(": ");
}

// One CSV line split into cells by libcsv; std::nullopt marks an empty, unquoted cell.
using Cells = std::vector<std::optional<std::string>>;

// libcsv's parser, owned; splits one line at a time so that errors know their line.
class CsvLineSplitter {
 public:
  CsvLineSplitter() {
    if (csv_init(&parser_, CSV_STRICT | CSV_STRICT_FINI | CSV_EMPTY_IS_NULL) != 0) {
      throw std::runtime_error("cannot initialise the CSV parser");
    }
  }
  ~CsvLineSplitter() { csv_free(&parser_); }
  CsvLineSplitter(const CsvLineSplitter&) = delete;
  CsvLineSplitter& operator=(const CsvLineSplitter&) = delete;

  Cells split(std::string_view line, const std::string& where) {
    Cells cells;
    // libcsv grows its cell buffer by a fixed block; a block as long as the line makes a huge
    // cell one allocation instead of a quadratic chain of reallocs.
    csv_set_blk_size(&parser_, std::max<std::size_t>(128, line.size() + 1));
    const std::size_t used = csv_parse(&parser_, line.data(), line.size(), on_cell, on_row, &cells);
    if (used != line.size() || csv_fini(&parser_, on_cell, on_row, &cells) != 0) {
      throw std::runtime_error(where + "malformed CSV (" + csv_strerror(csv_error(&parser_)) + ")");
    }
    return cells;
  }

 private:
  static void on_cell(void* cell, std::size_t length, void* data) {
    auto& cells = *static_cast<Cells*>(data);
    if (cell == nullptr) {
      cells.emplace_back(std::nullopt);
    } else {
      cells.emplace_back(std::string(static_cast<const char*>(cell), length));
    }
  }
  static void on_row(int /*terminator*/, void* /*data*/) {}

  csv_parser parser_{};
};

double parse_number(const std::optional<std::string>& cell, const std::string& where,
                    std::string_view column_name) {
  if (!cell || trim(*cell).empty()) {
    throw std::runtime_error(where + "missing value in column " + files::excerpt(column_name));
  }
  const std::string_view text = trim(*cell);
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    throw std::runtime_error(where + files::excerpt(text) + " in column " +
                             files::excerpt(column_name) + " is not a number");
  }
  if (!std::isfinite(value)) {
    throw std::runtime_error(where + "value " + files::excerpt(text) + " in column " +
                             files::excerpt(column_name) + " is not finite");
  }
  return value;
}

std::string range_text(const QuantityInfo& q) {
  if (q.max == kInf) return ">= " + format_number(q.min);
  return format_number(q.min) + ".." + format_number(q.max);
}

// The header: "wavelength_nm" then unique, non-empty column names.
std::vector<std::string> parse_header(const Cells& cells, const std::string& source,
                                      std::size_t line) {
  if (cells.empty() || !cells[0] || trim(*cells[0]) != "wavelength_nm") {
    throw std::runtime_error(location(source, line, 1) +
                             "the header must start with 'wavelength_nm'");
  }
  if (cells.size() < 2) {
    throw std::runtime_error(location(source, line) + "the header names no sample column");
  }
  std::vector<std::string> names;
  std::set<std::string, std::less<>> seen;
  for (std::size_t c = 1; c < cells.size(); ++c) {
    const std::string name(cells[c] ? trim(*cells[c]) : std::string_view{});
    if (name.empty()) {
      throw std::runtime_error(location(source, line, c + 1) + "empty column name");
    }
    if (!seen.insert(name).second) {
      throw std::runtime_error(location(source, line, c + 1) + "column name " +
                               files::excerpt(name) + " appears twice");
    }
    names.push_back(name);
  }
  return names;
}

}  // namespace

std::string_view to_string(SpectralQuantity quantity) {
  return info(quantity).name;
}

SpectralQuantity parse_spectral_quantity(std::string_view text) {
  std::string known;
  for (const auto& q : kQuantities) {
    if (q.name == text) return q.quantity;
    known += (known.empty() ? "" : ", ") + std::string(q.name);
  }
  throw std::runtime_error("unknown quantity '" + std::string(text) + "' (known: " + known + ")");
}

const Spectrum* SpectralTable::find(std::string_view column_name) const {
  for (const auto& c : columns) {
    if (c.name == column_name) return &c;
  }
  return nullptr;
}

const Spectrum& SpectralTable::column(std::string_view column_name) const {
  if (const Spectrum* found = find(column_name)) return *found;
  std::string present;
  for (const auto& c : columns) present += (present.empty() ? "" : ", ") + c.name;
  throw std::runtime_error("no column '" + std::string(column_name) + "' (columns: " + present +
                           ")");
}

SpectralTable parse_spectral_csv(std::string_view text, const std::string& source_name) {
  SpectralTable table;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // per column
  CsvLineSplitter splitter;
  bool have_header = false;
  std::size_t line_number = 0;
  double previous_nm = 0.0;

  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view content = trim(line);
    if (content.empty()) continue;

    if (content.front() == '#') {  // "# key: value" metadata, or a plain comment
      const std::string_view body = content.substr(1);
      const auto colon = body.find(':');
      if (colon == std::string_view::npos || trim(body.substr(0, colon)).empty()) continue;
      const std::string key(trim(body.substr(0, colon)));
      const std::string value(trim(body.substr(colon + 1)));
      if (!table.metadata.emplace(key, value).second) {
        throw std::runtime_error(location(source_name, line_number, 1) + "metadata key " +
                                 files::excerpt(key) + " given twice");
      }
      table.metadata_lines[key] = line_number;
      if (key == "quantity") {
        try {
          table.quantity = parse_spectral_quantity(value);
        } catch (const std::exception& e) {
          throw std::runtime_error(location(source_name, line_number, 1) + e.what());
        }
      }
      continue;
    }

    const Cells cells = splitter.split(line, location(source_name, line_number));
    if (!have_header) {
      names = parse_header(cells, source_name, line_number);
      values.resize(names.size());
      have_header = true;
      continue;
    }
    if (cells.size() != names.size() + 1) {
      const std::size_t column = std::min(cells.size(), names.size() + 1) + 1;
      throw std::runtime_error(location(source_name, line_number, column) + "row has " +
                               std::to_string(cells.size()) + " cells, the header has " +
                               std::to_string(names.size() + 1));
    }
    const double nm =
        parse_number(cells[0], location(source_name, line_number, 1), "wavelength_nm");
    if (nm <= 0.0) {
      throw std::runtime_error(location(source_name, line_number, 1) + "wavelength " +
                               format_number(nm) + " nm is not positive");
    }
    if (!table.wavelengths_nm.empty() && nm <= previous_nm) {
      throw std::runtime_error(
          location(source_name, line_number, 1) + "wavelength " + format_number(nm) +
          " nm does not increase (previous row: " + format_number(previous_nm) + " nm)");
    }
    previous_nm = nm;
    table.wavelengths_nm.push_back(nm);
    const QuantityInfo& range = info(table.quantity);
    for (std::size_t c = 0; c < names.size(); ++c) {
      const std::string where = location(source_name, line_number, c + 2);
      const double value = parse_number(cells[c + 1], where, names[c]);
      if (value < range.min || value > range.max) {
        throw std::runtime_error(where + "value " + format_number(value) + " in column '" +
                                 names[c] + "' is outside " + range_text(range) + " for " +
                                 std::string(range.name));
      }
      values[c].push_back(value);
    }
  }

  if (!have_header) throw std::runtime_error(source_name + ": no header line 'wavelength_nm,...'");
  if (table.wavelengths_nm.empty()) throw std::runtime_error(source_name + ": no data rows");
  for (std::size_t c = 0; c < names.size(); ++c) {
    table.columns.push_back(Spectrum{names[c], table.wavelengths_nm, std::move(values[c])});
  }
  return table;
}

SpectralTable read_spectral_csv(const std::filesystem::path& path) {
  return parse_spectral_csv(files::read_whole_file(path, "spectral CSV"), path.string());
}

}  // namespace impasto::data
