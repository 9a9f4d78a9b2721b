#pragma once
// The readers of the settings parts the matchers share, at the level of an open SettingsReader
// (private to Sextant::matchers_yaml).
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/dof_mask.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/optimizer_settings.hpp"
#include "sextant/matchers/precision_stage.hpp"

namespace sextant {

/// Reads the optional key `key` (a list of names) into `mask`; InputError on bad names.
void read_dof_mask(SettingsReader& in, const std::string& key, DofMask& mask);

/// Reads min_points, max_eigen_ratio, min_spread and min_relative_spread at the reader's level.
void read_cell_stats_settings(SettingsReader& in, CellStatsSettings& s);

/// Reads the optimiser keys the NDT matchers share: solver (message lists `known_solvers`),
/// max_iterations, epsilon, step_control (none | line_search | more_thuente | trust_region |
/// trust_region_last; the boolean `line_search: true/false` means line_search / none), the
/// Moré–Thuente keys line_search_mu, line_search_eta, line_search_max_step, line_search_iterations
/// (MoreThuenteSettings) and dof.
void read_optimizer_settings(SettingsReader& in, const std::string& known_solvers, OptimizerSettings& s);

/// Reads precision_min_cell, precision_min_coverage, precision_max_eigen_ratio and precision_spacing_cells
/// at the reader's level.
void read_precision_settings(SettingsReader& in, PrecisionSettings& s);

}  // namespace sextant
