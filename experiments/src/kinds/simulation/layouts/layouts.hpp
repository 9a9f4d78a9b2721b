#pragma once
// The simulation kind's models: 2D simulations that need no dataset. A model is one file plus one
// line in the table of layouts.cpp: its `model:` name, the checks of its params, methods and
// reference, one run and its report.
//   simulation/room.cpp        — the room with a circle, ML-NDT (x, y, yaw) into the Ackermann
//                                EKF (eqs. 3.37–3.52); trajectory figure and the lag measured
//   simulation/monte_carlo.cpp — range–bearing point-landmark SLAM (eqs. 5.7–5.9), paired
//                                Monte Carlo of any filters (UKF vs RSPKF)
//
//   params:
//     model: room_2d             # or range_bearing
//     ...                        # the model's own keys (see each file; each reads `model` too)
//   methods:                     # room_2d: {name, matcher, settings};
//                                # range_bearing: {name, filter, settings}
//
// Every run draws from Rng(run.seed), the same for every method at one repetition (paired runs).
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {

/// Throws InputError (file, line, key) on any problem of params, methods or reference.
using SimulationValidate = void (*)(const ExperimentConfig& config);
using SimulationRun = void (*)(const ExperimentConfig& config, const RunSpec& run, RunRow& row);
using SimulationReport = ReportSection (*)(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                           const std::vector<const RunRow*>& rows);

struct SimulationLayout {
  const char* name = "";  ///< the value of `model:`
  SimulationValidate validate = nullptr;
  SimulationRun run = nullptr;
  SimulationReport report = nullptr;
};

/// The table, in the order the error message names them.
const std::vector<SimulationLayout>& simulation_layouts();
/// The line of params.model; InputError at its line when it is missing or not in the table.
const SimulationLayout& simulation_layout(const ExperimentConfig& config);

}  // namespace sextant
