#pragma once
// The `registration` kind's report sections, one file per layout:
//   registration/layouts/accuracy.cpp — E2: tables 5.1–5.4, error vs scan index
//   registration/layouts/convergence_basin.cpp    — E1: success maps over (tx, yaw), score vs iteration
//   registration/layouts/init_layer.cpp     — E4: table 5.8 (fail %, time, error per f × start layer)
// and the helpers they share (rows ↔ eval's RegistrationSample, the thesis' reference values).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "registration/settings.hpp"
#include "sextant/eval/registration_metrics.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/eval/thesis_tables.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// A rigid transform as 12 numbers (the 3×4 [R t], row-major) for RunRow::series, and back.
std::vector<double> isometry_to_series(const Eigen::Isometry3d& T);
/// NaN transform when the series is missing or malformed.
Eigen::Isometry3d series_to_isometry(const std::vector<double>& s);

/// The registration of one row, as eval's statistics take it.
RegistrationSample sample_of(const RunRow& row);
/// The odometry guess of one row against its ground truth; nullopt when the row has none.
std::optional<RegistrationSample> odometry_sample_of(const RunRow& row);
/// Stats settings of the experiment (axes, success criterion).
RegistrationStatsSettings stats_settings(const RegistrationParams& params);

/// The thesis' mean / std / max per parameter: {mean: [6 numbers or null], std: [...], max: [...]}.
ParameterReference read_parameter_reference(const YAML::Node& node, const std::string& file);
/// `node[key]` when `node` is a map holding `key`, else a null node. (yaml-cpp's const operator[]
/// returns an invalid node for a missing key, and asking that node anything but IsDefined() throws.)
YAML::Node child_or_null(const YAML::Node& node, const std::string& key);
/// A number under `key` of a map node, or nullopt.
std::optional<double> reference_number(const YAML::Node& node, const std::string& key);
/// A number cell, or missing for NaN / nullopt.
Cell number_or_missing(double value, int precision = -1);
Cell number_or_missing(const std::optional<double>& value, int precision = -1);
std::string format_number(double value, int precision = 2);

/// Checks the reference block of the chosen layout (InputError with file, line, key).
void check_registration_reference(const ExperimentConfig& config, const RegistrationParams& params);

ReportSection accuracy_report(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);
ReportSection basin_report(const ExperimentConfig& config, const RegistrationParams& params,
                           const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);
ReportSection init_layer_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);
ReportSection sampling_report(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);
ReportSection strategies_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);
ReportSection zero_guess_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);

}  // namespace sextant
