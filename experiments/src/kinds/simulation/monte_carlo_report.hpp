#pragma once
// E15's params and report layout (simulation/monte_carlo.cpp runs, this lays out figs 5.35–5.36,
// the error table and the claims).
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/filters/filter_spec.hpp"
#include "sextant/filters/range_bearing_sim.hpp"

namespace sextant {

struct MonteCarloParams {
  int landmarks = 20;
  double side = 50.0;  ///< [m]
  RangeBearingSimSettings sim;
  Eigen::Vector3d initial_sigma{1e-3, 1e-3, 1e-3};  ///< [m, m, rad]
  int record_every = 50;                            ///< [steps]
  double bias_band_position = 0.5;                  ///< [m]
  double bias_band_heading_deg = 0.5;               ///< [deg]
  std::string baseline = "ukf";
  std::string proposed = "rspkf";
};

/// Reads and checks `params` (InputError with file, line, key).
MonteCarloParams read_monte_carlo_params(const ExperimentConfig& config);
/// A method's filter: `{name, filter, settings}`, read and checked (InputError).
FilterSpec read_range_bearing_filter(const YAML::Node& node, const std::string& file);

ReportSection monte_carlo_report(const ExperimentConfig& config, const MonteCarloParams& params,
                                 const RangeBearingWorld& world, const std::vector<RunSpec>& runs,
                                 const std::vector<const RunRow*>& rows);

}  // namespace sextant
