#pragma once
// The `simulation` kind: 2D simulations that need no dataset, one file per model:
//   simulation/room.cpp        — the room with a circle, ML-NDT (x, y, yaw) into the Ackermann
//                                EKF (eqs. 3.37–3.52); trajectory figure and the lag measured
//   simulation/monte_carlo.cpp — range–bearing point-landmark SLAM (eqs. 5.7–5.9), paired
//                                Monte Carlo of any filters (UKF vs RSPKF)
//
//   params:
//     model: room_2d             # or range_bearing
//     ...                        # the model's own keys (see each file; each reads `model` too)
//   methods:                     # room_2d: {name, matcher, settings}; range_bearing: {name, filter,
//   settings}
//
// Every run draws from Rng(run.seed), the same for every method at one repetition (paired runs).
#include <memory>
#include <string>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {

/// One simulation model: validates its params and methods, runs, lays out its report.
class SimulationModel {
 public:
  virtual ~SimulationModel() = default;
  /// Throws InputError (file, line, key) on any problem of params, methods or reference.
  virtual void validate(const ExperimentConfig& config) const = 0;
  virtual void run(const ExperimentConfig& config, const RunSpec& run, RunRow& row) const = 0;
  virtual ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                               const std::vector<const RunRow*>& rows) const = 0;
};

std::unique_ptr<SimulationModel> make_room_2d_model();
std::unique_ptr<SimulationModel> make_range_bearing_model();

}  // namespace sextant
