#include "impasto/flakes/flake_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "impasto/files/confined_path.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/util/text.hpp"

namespace impasto::flakes {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

// Blanks dropped, as a string of its own (the fields outlive the line they came from).
std::string trim(std::string_view s) {
  return std::string(util::trim(s));
}

std::vector<std::string> split(std::string_view s, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const auto end = s.find(separator, start);
    parts.push_back(trim(s.substr(start, end - start)));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

std::vector<std::string> words(std::string_view s) {
  std::vector<std::string> out;
  std::istringstream in{std::string(s)};
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// A value read from line `line` of `origin`; errors name both.
struct Field {
  std::string value;
  int line = 0;
};

[[noreturn]] void fail(const std::string& origin, int line, const std::string& message) {
  throw std::runtime_error(origin + ":" + std::to_string(line) + ": " + message);
}

double parse_number(const std::string& text, const std::string& origin, int line,
                    const std::string& what) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) {
    fail(origin, line, what + ": " + files::excerpt(text) + " is not a number");
  }
  if (!std::isfinite(value)) fail(origin, line, what + ": must be finite");
  return value;
}

// The key = value lines of a flake paint file.
class KeyValues {
 public:
  KeyValues(const std::string& text, std::string origin) : origin_(std::move(origin)) {
    std::istringstream in(text);
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      const std::string content = trim(std::string_view(line).substr(0, line.find('#')));
      if (content.empty()) continue;
      const auto equals = content.find('=');
      if (equals == std::string::npos) fail(origin_, line_number, "expected 'key = value'");
      const std::string key = trim(std::string_view(content).substr(0, equals));
      const std::string value = trim(std::string_view(content).substr(equals + 1));
      if (key.empty() || value.empty()) fail(origin_, line_number, "expected 'key = value'");
      if (key == "orientation_point" || key == "film_layer") {
        repeated_[key].push_back({value, line_number});
      } else if (!single_.emplace(key, Field{value, line_number}).second) {
        fail(origin_, line_number, files::excerpt(key) + " given twice");
      }
    }
  }

  const std::string& origin() const { return origin_; }

  // Every key must be one the format knows.
  void check_known(const std::vector<std::string>& known) const {
    for (const auto& [key, field] : single_) {
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        fail(origin_, field.line, "unknown field " + files::excerpt(key));
      }
    }
  }

  bool has(const std::string& key) const { return single_.count(key) != 0; }

  const Field& field(const std::string& key) const {
    const auto it = single_.find(key);
    if (it == single_.end()) throw std::runtime_error(origin_ + ": missing field '" + key + "'");
    return it->second;
  }

  // A number within [low, high]; `fallback` when absent and not required.
  double number(const std::string& key, double low, double high,
                std::optional<double> fallback = std::nullopt) const {
    if (!has(key) && fallback) return *fallback;
    const Field& f = field(key);
    const double value = parse_number(f.value, origin_, f.line, key);
    if (value < low || value > high) {
      std::ostringstream range;
      range << key << " = " << f.value << " is outside [" << low << ", " << high << "]";
      fail(origin_, f.line, range.str());
    }
    return value;
  }

  const std::vector<Field>& repeated(const std::string& key) const {
    static const std::vector<Field> none;
    const auto it = repeated_.find(key);
    return it == repeated_.end() ? none : it->second;
  }

 private:
  std::string origin_;
  std::map<std::string, Field> single_;
  std::map<std::string, std::vector<Field>> repeated_;
};

OrientationDistribution parse_orientation(const KeyValues& kv) {
  OrientationDistribution o;
  const Field& kind = kv.field("orientation");
  if (kind.value == "gaussian") {
    o.kind = OrientationDistribution::Kind::gaussian;
    o.gaussian_sd_rad = kv.number("orientation_sd_deg", 0.5, 60.0) * kDegree;
    return o;
  }
  if (kind.value != "table") {
    fail(kv.origin(), kind.line, "orientation must be 'gaussian' or 'table'");
  }
  o.kind = OrientationDistribution::Kind::table;
  double peak = 0;
  for (const Field& point : kv.repeated("orientation_point")) {
    const auto w = words(point.value);
    if (w.size() != 2)
      fail(kv.origin(), point.line, "orientation_point: expected 'beta_deg density'");
    const double beta = parse_number(w[0], kv.origin(), point.line, "orientation_point angle");
    const double density = parse_number(w[1], kv.origin(), point.line, "orientation_point density");
    if (beta < 0.0 || beta > 90.0)
      fail(kv.origin(), point.line, "orientation_point angle outside [0, 90] degrees");
    if (density < 0.0) fail(kv.origin(), point.line, "orientation_point density is negative");
    if (!o.table_beta_rad.empty() && beta * kDegree <= o.table_beta_rad.back()) {
      fail(kv.origin(), point.line, "orientation_point angles must increase");
    }
    o.table_beta_rad.push_back(beta * kDegree);
    o.table_density.push_back(density);
    peak = std::max(peak, density);
  }
  if (o.table_beta_rad.size() < 2 || !(peak > 0.0)) {
    throw std::runtime_error(kv.origin() +
                             ": orientation = table needs at least two orientation_point lines "
                             "with some positive density");
  }
  return o;
}

FlakeCoating parse_coating(const KeyValues& kv, const std::filesystem::path& folder) {
  const Field& kind = kv.field("coating");
  if (kind.value == "metal") {
    // The table lies beside the flake file, in its library: no path leads out of it.
    const Field& table = kv.field("nk_table");
    return load_nk_table(files::confined_path(
        folder, table.value, kv.origin() + ":" + std::to_string(table.line) + ": nk_table"));
  }
  if (kind.value != "thin_film")
    fail(kv.origin(), kind.line, "coating must be 'metal' or 'thin_film'");
  FlakeCoating coating;
  coating.kind = FlakeCoating::Kind::thin_film;
  for (const Field& layer : kv.repeated("film_layer")) {
    const auto w = words(layer.value);
    if (w.size() != 2)
      fail(kv.origin(), layer.line, "film_layer: expected 'material thickness_nm'");
    FilmLayerSpec spec;
    if (w[0] == "rutile") {
      spec.material.name = "rutile";
    } else {
      spec.material.constant_index =
          parse_number(w[0], kv.origin(), layer.line, "film_layer index");
      if (spec.material.constant_index < 1.0 || spec.material.constant_index > 5.0) {
        fail(kv.origin(), layer.line, "film_layer index outside [1, 5] (or use 'rutile')");
      }
    }
    spec.thickness_nm = parse_number(w[1], kv.origin(), layer.line, "film_layer thickness");
    if (!(spec.thickness_nm > 0.0) || spec.thickness_nm > 1e5) {
      fail(kv.origin(), layer.line, "film_layer thickness outside (0, 100000] nm");
    }
    coating.layers.push_back(spec);
  }
  if (coating.layers.empty()) {
    throw std::runtime_error(kv.origin() + ": coating = thin_film needs film_layer lines");
  }
  coating.core_index = kv.number("flake_core_index", 1.0, 5.0, 0.0);
  return coating;
}
}  // namespace

FlakePaint parse_flake_paint(const std::string& text, const std::string& origin,
                             const std::filesystem::path& folder) {
  const KeyValues kv(text, origin);
  kv.check_known({"format", "name", "source", "area_density_per_mm", "flake_area_mean_mm2",
                  "flake_area_sd_mm2", "orientation", "orientation_sd_deg", "coating", "nk_table",
                  "flake_core_index", "binder_ior", "binder_absorption_per_mm",
                  "rayleigh_weight_per_mm"});
  const Field& format = kv.field("format");
  if (format.value != "impasto-flake-paint 1") {
    fail(origin, format.line, "format must be 'impasto-flake-paint 1'");
  }
  FlakePaint paint;
  paint.name = kv.field("name").value;
  paint.area_density_per_mm = kv.number("area_density_per_mm", 1e-6, 1e4);
  paint.flake_area_mean_mm2 = kv.number("flake_area_mean_mm2", 1e-8, 1.0);
  paint.flake_area_sd_mm2 = kv.number("flake_area_sd_mm2", 0.0, 10.0 * paint.flake_area_mean_mm2);
  paint.orientation = parse_orientation(kv);
  paint.binder_index = kv.number("binder_ior", 1.0, 3.0);
  paint.binder_absorption_per_mm = kv.number("binder_absorption_per_mm", 0.0, 1e4, 0.0);
  paint.rayleigh_weight_per_mm = kv.number("rayleigh_weight_per_mm", 0.0, 1e4, 0.0);
  paint.coating = parse_coating(kv, folder);
  if (kv.has("source")) paint.coating.source = kv.field("source").value;
  return paint;
}

FlakePaint load_flake_paint(const std::filesystem::path& file) {
  return parse_flake_paint(files::read_whole_file(file, "flake paint file"), file.string(),
                           file.parent_path());
}

FlakeCoating parse_nk_table(const std::string& text, const std::string& origin) {
  FlakeCoating coating;
  coating.kind = FlakeCoating::Kind::metal;
  std::istringstream in(text);
  int line_number = 0;
  bool header_seen = false;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::string content = trim(line);
    if (content.empty()) continue;
    if (content[0] == '#') {
      const std::string comment = trim(std::string_view(content).substr(1));
      if (comment.rfind("source:", 0) == 0) coating.source = trim(comment.substr(7));
      continue;
    }
    const auto cells = split(content, ',');
    if (!header_seen) {
      header_seen = true;
      if (cells.size() == 3 && cells[0] == "wavelength_nm" && cells[1] == "n" && cells[2] == "k") {
        continue;
      }
      fail(origin, line_number, "expected the header 'wavelength_nm,n,k'");
    }
    if (cells.size() != 3) fail(origin, line_number, "expected 3 columns: wavelength_nm,n,k");
    const double nm = parse_number(cells[0], origin, line_number, "wavelength_nm");
    const double n = parse_number(cells[1], origin, line_number, "n");
    const double k = parse_number(cells[2], origin, line_number, "k");
    if (nm < 100.0 || nm > 100000.0)
      fail(origin, line_number, "wavelength_nm outside [100, 100000]");
    if (!coating.wavelengths_nm.empty() && nm <= coating.wavelengths_nm.back()) {
      fail(origin, line_number, "wavelengths must increase");
    }
    if (!(n > 0.0) || k < 0.0) fail(origin, line_number, "need n > 0 and k >= 0");
    coating.wavelengths_nm.push_back(nm);
    coating.n.push_back(n);
    coating.k.push_back(k);
  }
  if (coating.wavelengths_nm.size() < 2) {
    throw std::runtime_error(origin + ": an n, k table needs at least two rows");
  }
  return coating;
}

FlakeCoating load_nk_table(const std::filesystem::path& file) {
  return parse_nk_table(files::read_whole_file(file, "n,k table"), file.string());
}

}  // namespace impasto::flakes
