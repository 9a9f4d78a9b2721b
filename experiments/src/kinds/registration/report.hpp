#pragma once
// What the `registration` kind's report layouts share (one file per layout in
// registration/layouts/, one line each in the table of registration/layouts/layouts.cpp): rows as
// eval's RegistrationSample, the stats settings, the thesis' per-parameter reference.
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
/// Checks one method's accuracy block: {table, mean, std, max, success_percent, seconds, …}.
void check_accuracy_method(const YAML::Node& node, const std::string& file);
/// Checks each value of the map `node` (key `key`; absent or null: nothing) with `check`.
void check_map_of(const YAML::Node& node, const std::string& file, const std::string& key,
                  void (*check)(const YAML::Node&, const std::string&));

}  // namespace sextant
