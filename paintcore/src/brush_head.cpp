#include "impasto/paintcore/brush_head.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "impasto/files/data_dir.hpp"
#include "impasto/files/input_file.hpp"

namespace impasto::paintcore {

double BrushHead::field(double u, double v) const {
  double f = base(u, v);
  for (const Perturbation& p : perturbations) {
    const double q = p.shape(u, v);
    if (q > 0.0) f += p.factor * q * q * q;
  }
  return f;
}

double BrushHead::height(double u, double v) const {
  return rise * (1.0 - std::clamp(field(u, v), 0.0, 1.0));
}

long BrushHead::bristle_column(double u_mm) const {
  if (!(bristles.spacing_mm > 0.0)) return 0;
  // A column's tip lies at the head's centre line (u = 0): a narrow head is one bristle.
  return std::lround(std::floor(u_mm / bristles.spacing_mm + 0.5));
}

double BrushHead::bristle_height_mm(double u_mm) const {
  const Bristles& b = bristles;
  if (b.spacing_mm <= 0.0 || b.depth_mm <= 0.0) return 0.0;
  const long column = bristle_column(u_mm);
  const double phase = u_mm / b.spacing_mm + 0.5 - static_cast<double>(column);  // tip at 0.5
  // Each column's length varies by a fixed pseudo-random amount (the same on every run).
  auto bits = static_cast<std::uint64_t>(static_cast<std::int64_t>(column)) * 0x9E3779B97F4A7C15ull;
  bits ^= bits >> 31;
  bits *= 0xBF58476D1CE4E5B9ull;
  bits ^= bits >> 29;
  const double unit = static_cast<double>(bits >> 11) * 0x1.0p-53;  // [0, 1)
  // A rounded tip: 0 at the column's middle, rising to depth_mm at its edges.
  const double gap = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * (phase - 0.5)));
  return b.depth_mm * (gap + b.jitter * unit);
}

namespace {

struct LineParser {
  const std::string& source;
  int line_number;

  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(source + ":" + std::to_string(line_number) + ": " + why);
  }

  // Reads exactly `count` finite numbers after keyword `key`.
  std::vector<double> numbers(std::istringstream& words, const std::string& key,
                              std::size_t count) const {
    std::vector<double> values;
    std::string word;
    while (words >> word) {
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0')
        fail("'" + key + "' expects numbers, got '" + word + "'");
      if (!std::isfinite(value)) fail("'" + key + "' has a value that is not finite");
      values.push_back(value);
    }
    if (values.size() != count)
      fail("'" + key + "' expects " + std::to_string(count) + " numbers, got " +
           std::to_string(values.size()));
    return values;
  }
};

Quadric2 quadric_from(const std::vector<double>& c, std::size_t first) {
  return {c[first], c[first + 1], c[first + 2], c[first + 3], c[first + 4], c[first + 5]};
}

std::string rest_of_line(std::istringstream& words) {
  std::string rest;
  std::getline(words >> std::ws, rest);
  return rest;
}

}  // namespace

BrushHead parse_brush_head(std::istream& in, const std::string& source) {
  BrushHead head;
  bool seen_header = false;
  bool seen_base = false;
  std::string text;
  int line_number = 0;
  while (std::getline(in, text)) {
    ++line_number;
    const LineParser parser{source, line_number};
    if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    std::string key;
    if (!(words >> key)) continue;  // blank or comment
    if (!seen_header) {
      if (key != "impasto-brush")
        parser.fail("expected the header 'impasto-brush 1', got '" + key + "'");
      const auto version = parser.numbers(words, key, 1);
      if (version[0] != 1.0)
        parser.fail("unsupported brush format version " + std::to_string(version[0]));
      seen_header = true;
    } else if (key == "name") {
      head.name = rest_of_line(words);
      if (head.name.empty()) parser.fail("'name' needs a value");
    } else if (key == "description") {
      head.description = rest_of_line(words);
    } else if (key == "rise") {
      head.rise = parser.numbers(words, key, 1)[0];
      if (head.rise < 0.0 || head.rise > 100.0) parser.fail("'rise' must be in 0..100");
    } else if (key == "base") {
      if (seen_base) parser.fail("'base' given twice");
      head.base = quadric_from(parser.numbers(words, key, 6), 0);
      seen_base = true;
    } else if (key == "perturb") {
      if (head.perturbations.size() >= kMaxPerturbations)
        parser.fail("more than " + std::to_string(kMaxPerturbations) + " perturbations");
      const auto c = parser.numbers(words, key, 7);
      head.perturbations.push_back({c[0], quadric_from(c, 1)});
    } else if (key == "bristles") {
      const auto c = parser.numbers(words, key, 3);
      static constexpr const char* kParts[] = {"spacing", "depth", "jitter"};
      for (std::size_t i = 0; i < 3; ++i) {
        const BristleSetting& setting = kBristleSettings[i];
        if (!setting.holds(c[i]))
          parser.fail("'bristles' " + std::string(kParts[i]) + " must be in " +
                      setting.range_text());
        setting.of(head) = c[i];
      }
    } else if (key == "splay") {
      const BristleSetting& setting = *find_bristle_setting("splay");
      setting.of(head) = parser.numbers(words, key, 1)[0];
      if (!setting.holds(head.splay)) parser.fail("'splay' must be in " + setting.range_text());
    } else {
      parser.fail("unknown key '" + key + "'");
    }
  }
  if (in.bad()) throw std::runtime_error(source + ": read error");
  if (!seen_header) throw std::runtime_error(source + ": empty file (no 'impasto-brush 1' header)");
  if (!seen_base) throw std::runtime_error(source + ": missing 'base' quadric");
  if (head.name.empty()) throw std::runtime_error(source + ": missing 'name'");
  if (!head.covers(0.0, 0.0))
    throw std::runtime_error(source + ": the head does not cover its centre (F'(0,0) <= 0)");
  return head;
}

BrushHead load_brush_head(const std::filesystem::path& file) {
  // Through the bounded reader: folders and devices refused by name, the size capped (a head
  // is a few lines; 1 MB is generous).
  std::istringstream in(files::read_whole_file(file, "brush head file", std::uint64_t{1} << 20));
  return parse_brush_head(in, file.string());
}

std::filesystem::path default_brushes_dir() {
  return files::data_dir() / "brushes";
}

BrushHead load_named_brush_head(const std::string& name, const std::filesystem::path& dir) {
  const bool valid = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (!valid)
    throw std::runtime_error("brush settings: field 'head' must be a plain name, got '" + name +
                             "'");
  return load_brush_head(dir / (name + ".brush"));
}

}  // namespace impasto::paintcore
