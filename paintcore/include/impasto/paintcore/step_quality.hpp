#pragma once
// How finely the simulation steps a brush along its path: the trade between speed and
// accuracy a painter chooses (the window's Quality, `quality` records in a stroke file,
// `impasto replay --quality`; docs/simulation.md, "Quality"). A level is a setting of the
// long steps' three parameters (simulation_params.hpp); the rest of the model is the same, and
// heads under long_step_from_cells across step a cell at a time at every level.
#include <optional>

#include "impasto/paintcore/simulation_params.hpp"
#include "impasto/util/enum_names.hpp"

namespace impasto::paintcore {

enum class StepQuality {
  exact,     // every head steps a cell at a time: the reference
  balanced,  // SimulationParams' own long steps
  fast,      // longer steps and sub-steps: faster on big heads, a faint ripple along a stroke
};

inline constexpr util::EnumNames<StepQuality, 3> kStepQualityNames{{
    {StepQuality::exact, "exact"},
    {StepQuality::balanced, "balanced"},
    {StepQuality::fast, "fast"},
}};

// `params` with the long steps of `quality` (its other parameters kept).
SimulationParams with_step_quality(SimulationParams params, StepQuality quality);
// The level whose long steps `params` has, if any.
std::optional<StepQuality> step_quality_of(const SimulationParams& params);

}  // namespace impasto::paintcore
