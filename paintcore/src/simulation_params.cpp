#include "impasto/paintcore/simulation_params.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/painting_file_header.hpp"
#include "impasto/util/text.hpp"

namespace impasto::paintcore {
namespace {

// One source for the parameters: names, file versions (painting_file_io.hpp says what each
// version added), ranges and meanings.
constexpr NamedParam kNamedParams[] = {
    {"deposit_share", &SimulationParams::deposit_share, 3, 0, 1, false, "",
     "the canvas's share of the joint film when brush and canvas part"},
    {"transfer_length_mm", &SimulationParams::transfer_length_mm, 3, 0, 1000, true, "mm",
     "distance over which the split is reached (1/e)"},
    {"transfer_time_s", &SimulationParams::transfer_time_s, 3, 0, 3600, true, "s",
     "time over which a still, pressed brush reaches it (1/e)"},
    {"lift_share", &SimulationParams::lift_share, 3, 0, 1, false, "",
     "the canvas's share of the film where the brush lifts"},
    {"tip_film_mm", &SimulationParams::tip_film_mm, 3, 0, 1000, true, "mm",
     "the most paint a brush cell's tips present to the split"},
    {"ground_fill", &SimulationParams::ground_fill, 3, 0, 1, false, "",
     "share of a valley below the brush's footing that pressed paint fills (a film thinner "
     "than the valley fills less)"},
    {"brush_flow_length_mm", &SimulationParams::brush_flow_length_mm, 3, 0, 1000, true, "mm",
     "paint in the bristles evens out over this distance"},
    {"plough", &SimulationParams::plough, 3, 0, 100, false, "",
     "squeeze: mm of paint displacement per mm travelled per unit slope of p"},
    {"drag", &SimulationParams::drag, 3, 0, 1, false, "",
     "the touched paint moves with this share of the brush's velocity"},
    {"squeeze_mm_s", &SimulationParams::squeeze_mm_s, 3, 0, 1000, false, "mm/s",
     "squeeze of a still brush: mm/s per unit slope of p"},
    {"min_film_mm", &SimulationParams::min_film_mm, 3, 0, 1000, false, "mm",
     "film that advection never removes (adhesion)"},
    {"settle_time_s", &SimulationParams::settle_time_s, 3, 0, 3600, false, "s",
     "how long a stroke's paint levels after it ends"},
    {"wet_support", &SimulationParams::wet_support, 3, 0, 1, false, "",
     "share of the wet paint that holds the brush up"},
    {"long_step_share", &SimulationParams::long_step_share, 7, 0, 0.5, false, "",
     "a big brush's longest step, as a share of its width (0: one cell)"},
    {"long_step_from_cells", &SimulationParams::long_step_from_cells, 7, 0, 1e6, true, "cells",
     "the narrowest brush (cells across) that takes long steps"},
    {"long_step_drag_cells", &SimulationParams::long_step_drag_cells, 7, 1, 1e6, false, "cells",
     "a long step's drag is advected in sub-steps of at most this travel (cells)"},
    {"touch_mm", &SimulationParams::touch_mm, 9, 0, 1000, false, "mm",
     "the depth over which the film split and the drag fade in from the contact's edge"},
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

const NamedParam* find_simulation_param(std::string_view name) {
  for (const NamedParam& p : kNamedParams)
    if (name == p.name) return &p;
  return nullptr;
}

void set_param(SimulationParams& params, const std::string& assignment) {
  const auto equals = assignment.find('=');
  const std::string name = assignment.substr(0, equals);
  if (const NamedParam* found = find_simulation_param(name)) {
    const NamedParam& p = *found;
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

std::string NamedParam::out_of_range(double value) const {
  if (std::isfinite(value) && (lowest_excluded ? value > lowest : value >= lowest) &&
      value <= highest)
    return "";
  const auto shown = [](double v) { return util::number_text(v); };
  return std::string("must be in ") + (lowest_excluded ? "(" : "[") + shown(lowest) + ", " +
         shown(highest) + "]" + (*unit != '\0' ? std::string(" ") + unit : "") + ", got " +
         shown(value);
}

void validate(const SimulationParams& p) {
  for (const NamedParam& row : kNamedParams)
    if (std::string why = row.out_of_range(p.*row.field); !why.empty())
      throw std::runtime_error(std::string("simulation params: field '") + row.name + "' " + why);
}

}  // namespace impasto::paintcore
