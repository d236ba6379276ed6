#include "impasto/cracks/cavity_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "impasto/cracks/monte_carlo.hpp"
#include "impasto/data/data_dir.hpp"
#include "impasto/files/input_file.hpp"

namespace impasto::cracks {
namespace {

double grid_ratio(const CavityTableGrid& g, int i) {
  return g.ratio_min * std::pow(10.0, static_cast<double>(i) / g.ratios_per_decade);
}
double grid_rho0(const CavityTableGrid& g, int j) {
  return static_cast<double>(j) / (g.rho0_count - 1);
}

void check_grid(const CavityTableGrid& g, const std::string& where) {
  if (!(g.ratio_min > 0.0 && std::isfinite(g.ratio_min)) || g.ratios_per_decade < 1 ||
      g.ratios_per_decade > 100 || g.ratio_count < 2 || g.ratio_count > 1000 || g.rho0_count < 2 ||
      g.rho0_count > 1000) {
    throw std::runtime_error(where + ": bad cavity table grid");
  }
}

}  // namespace

std::string to_string(const CavityLight& light) {
  if (light.diffuse) return "diffuse";
  std::ostringstream text;
  text << "beam:" << light.zenith_deg;
  return text.str();
}

CavityLight parse_cavity_light(std::string_view text) {
  if (text == "diffuse") return CavityLight::sky();
  if (text.rfind("beam:", 0) == 0) {
    const std::string number(text.substr(5));
    std::size_t used = 0;
    double zenith = -1.0;
    try {
      zenith = std::stod(number, &used);
    } catch (const std::exception&) {
    }
    if (used == number.size() && zenith >= 0.0 && zenith < 90.0) return CavityLight::beam(zenith);
  }
  throw std::runtime_error("unknown cavity light '" + std::string(text) +
                           "' (expected diffuse or beam:ZENITH_DEG, 0 <= ZENITH_DEG < 90)");
}

double CavityTable::ratio(int i) const {
  return grid_ratio(grid_, i);
}
double CavityTable::rho0(int j) const {
  return grid_rho0(grid_, j);
}

CavityTable CavityTable::measure(const CavityTableGrid& grid, CavityLight light,
                                 std::uint64_t paths, std::uint64_t seed,
                                 const util::ProgressCallback& progress) {
  check_grid(grid, "cavity table");
  CavityTable table;
  table.grid_ = grid;
  table.light_ = light;
  const Illumination illumination =
      light.diffuse ? Illumination::diffuse()
                    : Illumination::directional(light.zenith_deg * std::numbers::pi / 180.0);
  table.rho_.resize(kAllShapes.size() * static_cast<std::size_t>(grid.ratio_count) *
                    static_cast<std::size_t>(grid.rho0_count));
  const MonteCarloSettings settings{paths, seed, MonteCarloSettings{}.max_bounces};
  const std::uint64_t traces = kAllShapes.size() * static_cast<std::uint64_t>(grid.ratio_count);
  std::uint64_t traced = 0;
  for (CavityShape shape : kAllShapes) {
    for (int i = 0; i < grid.ratio_count; ++i) {
      const EscapeHistogram h =
          trace_cavity(shape, {grid_ratio(grid, i), 1.0}, illumination, settings);
      for (int j = 0; j < grid.rho0_count; ++j) {
        const double rho0 = grid_rho0(grid, j);
        // Deeper is darker and no cavity is brighter than its walls: the running minimum
        // removes the reference's noise where two rows differ by less than it.
        double rho = std::min(h.apparent_reflectance(rho0), rho0);
        if (i > 0) rho = std::min(rho, static_cast<double>(table.reflectance_at(shape, i - 1, j)));
        table.rho_[table.index(shape, i, j)] = static_cast<float>(rho);
      }
      if (progress) progress(++traced, traces);
    }
  }
  table.compute_differences();
  return table;
}

void CavityTable::write_csv(std::ostream& out) const {
  out << "# Apparent reflectance rho of a cavity (Monte Carlo reference), non-increasing in "
         "L/R.\n"
      << "# light: " << to_string(light_) << "\n"
      << "# grid: ratio_min " << grid_.ratio_min << " ratios_per_decade " << grid_.ratios_per_decade
      << " ratio_count " << grid_.ratio_count << " rho0_count " << grid_.rho0_count << "\n"
      << "shape,L_over_R,rho0,rho\n";
  out.precision(9);
  for (CavityShape shape : kAllShapes) {
    for (int i = 0; i < grid_.ratio_count; ++i) {
      for (int j = 0; j < grid_.rho0_count; ++j) {
        out << shape_name(shape) << ',' << grid_ratio(grid_, i) << ',' << grid_rho0(grid_, j) << ','
            << reflectance_at(shape, i, j) << '\n';
      }
    }
  }
}

CavityTable CavityTable::read_csv(const std::filesystem::path& path) {
  files::InputFile file(path, "cavity table", files::kMaxTextFileBytes);
  std::istream& in = file.stream();
  CavityTable table;
  std::string line;
  int line_no = 0;
  bool have_grid = false, have_header = false, have_light = false;
  std::size_t next = 0;
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(path.string() + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    if (line.rfind("# grid:", 0) == 0) {
      std::istringstream s(line.substr(7));
      std::string a, b, c, d;
      CavityTableGrid& g = table.grid_;
      if (!(s >> a >> g.ratio_min >> b >> g.ratios_per_decade >> c >> g.ratio_count >> d >>
            g.rho0_count) ||
          a != "ratio_min" || b != "ratios_per_decade" || c != "ratio_count" || d != "rho0_count") {
        fail("malformed grid line");
      }
      check_grid(g, path.string() + ":" + std::to_string(line_no));
      table.rho_.assign(kAllShapes.size() * static_cast<std::size_t>(g.ratio_count) *
                            static_cast<std::size_t>(g.rho0_count),
                        0.0f);
      have_grid = true;
      continue;
    }
    if (line.rfind("# light:", 0) == 0) {
      std::string name = line.substr(8);
      name.erase(0, name.find_first_not_of(' '));
      try {
        table.light_ = parse_cavity_light(name);
      } catch (const std::runtime_error& e) {
        fail(e.what());
      }
      have_light = true;
      continue;
    }
    if (line[0] == '#') continue;
    if (!have_header) {
      if (!have_light) fail("expected '# light: beam:ZENITH_DEG' or '# light: diffuse' first");
      if (line != "shape,L_over_R,rho0,rho") fail("expected the header shape,L_over_R,rho0,rho");
      have_header = true;
      continue;
    }
    if (!have_grid) fail("data before the '# grid:' line");
    if (next >= table.rho_.size()) fail("more rows than the grid holds");
    // Rows come in the order write_csv writes them; check that each names its grid point.
    const int j = static_cast<int>(next % static_cast<std::size_t>(table.grid_.rho0_count));
    const int i = static_cast<int>((next / static_cast<std::size_t>(table.grid_.rho0_count)) %
                                   static_cast<std::size_t>(table.grid_.ratio_count));
    const auto shape = kAllShapes[next / (static_cast<std::size_t>(table.grid_.rho0_count) *
                                          static_cast<std::size_t>(table.grid_.ratio_count))];
    std::istringstream s(line);
    std::string name, ratio, rho0, rho;
    if (!std::getline(s, name, ',') || !std::getline(s, ratio, ',') ||
        !std::getline(s, rho0, ',') || !std::getline(s, rho)) {
      fail("expected 4 fields");
    }
    if (name != shape_name(shape)) fail("expected shape " + std::string(shape_name(shape)));
    double r = 0, p = 0, kv = 0;
    try {
      r = std::stod(ratio);
      p = std::stod(rho0);
      kv = std::stod(rho);
    } catch (const std::exception&) {
      fail("a field is not a number");
    }
    if (std::abs(r / grid_ratio(table.grid_, i) - 1.0) > 1e-6) fail("L_over_R off the grid");
    if (std::abs(p - grid_rho0(table.grid_, j)) > 1e-6) fail("rho0 off the grid");
    if (!std::isfinite(kv) || kv < 0.0 || kv > 1.0) fail("field rho must be in [0, 1]");
    table.rho_[next++] = static_cast<float>(kv);
  }
  if (!have_grid || next != table.rho_.size()) {
    throw std::runtime_error(path.string() + ": cavity table incomplete (" + std::to_string(next) +
                             " rows)");
  }
  table.compute_differences();
  return table;
}

double CavityTable::ratio_coordinate(double depth_over_half_width) const {
  const double r = std::max(depth_over_half_width, 0.0);
  if (r < grid_.ratio_min) return r / grid_.ratio_min - 1.0;  // [-1, 0): towards L = 0
  return std::log10(r / grid_.ratio_min) * grid_.ratios_per_decade;
}

void CavityTable::compute_differences() {
  difference_.resize(rho_.size());
  for (CavityShape shape : kAllShapes) {
    for (int i = 0; i < grid_.ratio_count; ++i) {
      const ViewFactors vf = view_factors(shape, {ratio(i), 1.0});
      for (int j = 0; j < grid_.rho0_count; ++j) {
        const std::size_t k = index(shape, i, j);
        difference_[k] = static_cast<float>(rho_[k] - apparent_reflectance(rho0(j), vf));
      }
    }
  }
}

double CavityTable::clamp_to_walls(double rho, double rho0) {
  return std::clamp(rho, 0.0, std::clamp(rho0, 0.0, 1.0));
}

double CavityTable::difference_at(CavityShape shape, double u, double rho0,
                                  const ViewFactors& vf) const {
  return interpolate_difference(grid_, difference_, shape, u, rho0, vf);
}

double interpolate_difference(const CavityTableGrid& g, std::span<const float> differences,
                              CavityShape shape, double u, double rho0, const ViewFactors& vf) {
  const int last = g.ratio_count - 1;
  const double uc = std::clamp(u, 0.0, static_cast<double>(last));
  const double v = std::clamp(rho0, 0.0, 1.0) * (g.rho0_count - 1);
  const int i0 = std::min(static_cast<int>(uc), last - 1);
  const int j0 = std::min(static_cast<int>(v), g.rho0_count - 2);
  const double fu = uc - i0, fv = v - j0;
  const auto at = [&](int i, int j) {
    return static_cast<double>(
        differences[(static_cast<std::size_t>(shape) * static_cast<std::size_t>(g.ratio_count) +
                     static_cast<std::size_t>(i)) *
                        static_cast<std::size_t>(g.rho0_count) +
                    static_cast<std::size_t>(j)]);
  };
  double difference = (1 - fu) * ((1 - fv) * at(i0, j0) + fv * at(i0, j0 + 1)) +
                      fu * ((1 - fv) * at(i0 + 1, j0) + fv * at(i0 + 1, j0 + 1));
  if (u < 0.0) {
    difference *= u + 1.0;  // fades out towards L = 0, where the closed form is exact
  } else if (u > last) {
    // Deeper than the grid: the difference decays as the closed form itself does.
    const double gouffe = apparent_reflectance(rho0, vf);
    const double gouffe_last =
        apparent_reflectance(rho0, view_factors(shape, {grid_ratio(g, last), 1.0}));
    difference *= gouffe_last > 0.0 ? std::min(1.0, gouffe / gouffe_last) : 0.0;
  }
  return difference;
}

namespace {

CavityTable read_shipped(const std::string& name, const CavityLight& light) {
  const auto path = data::data_dir() / "cracks" / name;
  CavityTable table = CavityTable::read_csv(path);
  if (!(table.light() == light)) {
    throw std::runtime_error(path.string() + ": measured under " + to_string(table.light()) +
                             ", expected " + to_string(light));
  }
  return table;
}

void check_same_grid(const CavityTable& a, const CavityTable& b, const std::string& name) {
  if (a.grid() != b.grid()) {
    throw std::runtime_error((data::data_dir() / "cracks" / name).string() +
                             ": grid differs from the axial table's");
  }
}

std::string beam_file(double zenith_deg) {
  return "cavity_table_beam_" + std::to_string(static_cast<int>(zenith_deg)) + ".csv";
}

}  // namespace

const CavityTable& shipped_beam_table(int zenith_index) {
  static const std::vector<CavityTable> tables = [] {
    std::vector<CavityTable> list;
    for (double zenith : kShippedBeamZenithsDeg) {
      list.push_back(read_shipped(beam_file(zenith), CavityLight::beam(zenith)));
      check_same_grid(list.front(), list.back(), beam_file(zenith));
    }
    return list;
  }();
  return tables.at(static_cast<std::size_t>(zenith_index));
}

const CavityTable& shipped_sky_table() {
  static const CavityTable table = [] {
    CavityTable sky = read_shipped("cavity_table_diffuse.csv", CavityLight::sky());
    check_same_grid(shipped_cavity_table(), sky, "cavity_table_diffuse.csv");
    return sky;
  }();
  return table;
}

}  // namespace impasto::cracks
