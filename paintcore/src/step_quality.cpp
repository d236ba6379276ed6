#include "impasto/paintcore/step_quality.hpp"

namespace impasto::paintcore {
namespace {

struct LongSteps {
  double share, from_cells, drag_cells;
};

LongSteps long_steps_of(StepQuality quality) {
  const SimulationParams defaults;
  switch (quality) {
    case StepQuality::exact:
      return {0.0, defaults.long_step_from_cells, defaults.long_step_drag_cells};
    case StepQuality::balanced:
      return {defaults.long_step_share, defaults.long_step_from_cells,
              defaults.long_step_drag_cells};
    case StepQuality::fast:
      // Steps of an eighth of the head from 32 cells across, sub-steps of 2 cells: 1.5 times
      // as fast as balanced on a 256-cell head. Sub-steps over a cell print a faint ripple at
      // their spacing (4 cells: 2.2 times as fast, twice the ripple; docs/simulation.md,
      // "Quality").
      return {0.125, 32.0, 2.0};
  }
  return {defaults.long_step_share, defaults.long_step_from_cells, defaults.long_step_drag_cells};
}

}  // namespace

SimulationParams with_step_quality(SimulationParams params, StepQuality quality) {
  const LongSteps steps = long_steps_of(quality);
  params.long_step_share = steps.share;
  params.long_step_from_cells = steps.from_cells;
  params.long_step_drag_cells = steps.drag_cells;
  return params;
}

std::optional<StepQuality> step_quality_of(const SimulationParams& params) {
  for (const auto& entry : kStepQualityNames) {
    const LongSteps steps = long_steps_of(entry.value);
    if (params.long_step_share == steps.share &&
        (steps.share == 0.0 || (params.long_step_from_cells == steps.from_cells &&
                                params.long_step_drag_cells == steps.drag_cells)))
      return entry.value;
  }
  return std::nullopt;
}

}  // namespace impasto::paintcore
