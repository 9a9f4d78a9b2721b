#pragma once
// The `registration` kind's report sections, one file per layout in registration/layouts/
// (accuracy, convergence_basin, init_layer, sampling, strategies, zero_guess), and what they share:
// rows as eval's RegistrationSample, the stats settings, the reference-block checks
// (reference_checks.cpp).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "kit/number_format.hpp"
#include "kit/reference_values.hpp"
#include "kit/row_codec.hpp"
#include "registration/settings.hpp"
#include "sextant/eval/registration_metrics.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/eval/thesis_tables.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// The registration of one row, as eval's statistics take it.
RegistrationSample sample_of(const RunRow& row);
/// The odometry guess of one row against its ground truth; nullopt when the row has none.
std::optional<RegistrationSample> odometry_sample_of(const RunRow& row);
/// Stats settings of the experiment (axes, success criterion).
RegistrationStatsSettings stats_settings(const RegistrationParams& params);

/// The thesis' mean / std / max per parameter: {mean: [6 numbers or null], std: [...], max: [...]}.
ParameterReference read_parameter_reference(const YAML::Node& node, const std::string& file);

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
