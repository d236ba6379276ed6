#include "impasto/paintcore/simulation_params.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/painting_file_header.hpp"

namespace impasto::paintcore {
namespace {

// One source for the parameters' names, and for the painting file version that first holds
// each (painting_file_io.hpp says what each version added).
constexpr NamedParam kNamedParams[] = {
    {"deposit_share", &SimulationParams::deposit_share, 3},
    {"transfer_length_mm", &SimulationParams::transfer_length_mm, 3},
    {"transfer_time_s", &SimulationParams::transfer_time_s, 3},
    {"lift_share", &SimulationParams::lift_share, 3},
    {"tip_film_mm", &SimulationParams::tip_film_mm, 3},
    {"ground_fill", &SimulationParams::ground_fill, 3},
    {"brush_flow_length_mm", &SimulationParams::brush_flow_length_mm, 3},
    {"plough", &SimulationParams::plough, 3},
    {"drag", &SimulationParams::drag, 3},
    {"squeeze_mm_s", &SimulationParams::squeeze_mm_s, 3},
    {"min_film_mm", &SimulationParams::min_film_mm, 3},
    {"settle_time_s", &SimulationParams::settle_time_s, 3},
    {"wet_support", &SimulationParams::wet_support, 3},
    {"long_step_share", &SimulationParams::long_step_share, 7},
    {"long_step_from_cells", &SimulationParams::long_step_from_cells, 7},
    {"long_step_drag_cells", &SimulationParams::long_step_drag_cells, 7},
};
// Each file version's fields follow the older ones' (a file's are a prefix of the list), and
// the newest version writes every one.
static_assert(std::is_sorted(std::begin(kNamedParams), std::end(kNamedParams),
                             [](const NamedParam& a, const NamedParam& b) {
                               return a.file_version < b.file_version;
                             }));
static_assert(std::end(kNamedParams)[-1].file_version <= kPaintingFileVersion);

}  // namespace

std::span<const NamedParam> all_simulation_params() {
  return kNamedParams;
}

std::span<const NamedParam> simulation_param_fields(std::uint32_t file_version) {
  const auto end = std::find_if(std::begin(kNamedParams), std::end(kNamedParams),
                                [&](const NamedParam& p) { return p.file_version > file_version; });
  return std::span<const NamedParam>(std::begin(kNamedParams), end);
}

void set_param(SimulationParams& params, const std::string& assignment) {
  const auto equals = assignment.find('=');
  const std::string name = assignment.substr(0, equals);
  for (const NamedParam& p : kNamedParams) {
    if (name != p.name) continue;
    if (equals == std::string::npos)
      throw std::runtime_error("simulation params: '" + name + "' needs a value (NAME=VALUE)");
    const std::string text = assignment.substr(equals + 1);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(text, &used);
    } catch (const std::logic_error&) {
      used = 0;
    }
    if (used == 0 || used != text.size())
      throw std::runtime_error("simulation params: field '" + name + "' expects a number, got '" +
                               text.substr(0, 32) + "'");
    params.*p.field = value;
    return;
  }
  std::string known;
  for (const NamedParam& p : kNamedParams) known += std::string(known.empty() ? "" : ", ") + p.name;
  throw std::runtime_error("simulation params: unknown field '" + name.substr(0, 32) +
                           "' (known: " + known + ")");
}

void validate(const SimulationParams& p) {
  const auto check = [](double value, const char* field, bool positive) {
    if (!std::isfinite(value) || value < 0.0 || (positive && value == 0.0))
      throw std::runtime_error(std::string("simulation params: field '") + field + "' must be " +
                               (positive ? "positive" : "non-negative") + " and finite, got " +
                               std::to_string(value));
  };
  check(p.deposit_share, "deposit_share", false);
  if (p.deposit_share > 1.0)
    throw std::runtime_error("simulation params: field 'deposit_share' must be <= 1");
  check(p.lift_share, "lift_share", false);
  if (p.lift_share > 1.0)
    throw std::runtime_error("simulation params: field 'lift_share' must be <= 1");
  check(p.tip_film_mm, "tip_film_mm", true);
  check(p.ground_fill, "ground_fill", false);
  if (p.ground_fill > 1.0)
    throw std::runtime_error("simulation params: field 'ground_fill' must be <= 1");
  check(p.transfer_length_mm, "transfer_length_mm", true);
  check(p.transfer_time_s, "transfer_time_s", true);
  check(p.brush_flow_length_mm, "brush_flow_length_mm", true);
  check(p.plough, "plough", false);
  check(p.drag, "drag", false);
  if (p.drag > 1.0) throw std::runtime_error("simulation params: field 'drag' must be <= 1");
  check(p.squeeze_mm_s, "squeeze_mm_s", false);
  check(p.min_film_mm, "min_film_mm", false);
  check(p.settle_time_s, "settle_time_s", false);
  check(p.wet_support, "wet_support", false);
  if (p.wet_support > 1.0)
    throw std::runtime_error("simulation params: field 'wet_support' must be <= 1");
  check(p.long_step_share, "long_step_share", false);
  if (p.long_step_share > 0.5)
    throw std::runtime_error(
        "simulation params: field 'long_step_share' must be <= 0.5 (of the brush's width)");
  check(p.long_step_from_cells, "long_step_from_cells", true);
  if (p.long_step_from_cells > 1e6)
    throw std::runtime_error("simulation params: field 'long_step_from_cells' must be <= 1e6");
  check(p.long_step_drag_cells, "long_step_drag_cells", true);
  if (p.long_step_drag_cells < 1.0 || p.long_step_drag_cells > 1e6)
    throw std::runtime_error(
        "simulation params: field 'long_step_drag_cells' must be in [1, 1e6] (cells)");
  if (p.plough > 100.0 || p.squeeze_mm_s > 1000.0 || p.settle_time_s > 3600.0)
    throw std::runtime_error(
        "simulation params: 'plough' must be <= 100, 'squeeze_mm_s' <= 1000 and "
        "'settle_time_s' <= 3600");
}

}  // namespace impasto::paintcore
