#pragma once
// What E1's layout files share (registration/layouts/convergence_basin.cpp: tables, figures, notes;
// registration/layouts/convergence_basin_claims.cpp: the verdicts): the report settings under `reference:`
// and the runs grouped.
//
//   reference:
//     criterion: {translation_m: 0.5, rotation_deg: 2}   # success (ours; §5.1.1.1 states none)
//     basin_rate: 0.5                                # a grid value is inside the basin at ≥ this rate
//     thesis:                                        # §5.1.1.1, in its unnamed "units"
//       ndt: {max_translation: 10, max_yaw_deg: 5, settle_iterations: 25}
//       mlndt: {max_translation: 25, max_yaw_deg: 15, settle_iterations: 5}   # "a few"
//     bands: {translation_ratio: [1.67, 3.75], yaw_ratio: [2, 4.5], ndt_settle: [12.5, 50],
//             solver_success_difference: 0.1}
//     compare_solvers: {newton: mlndt_newton_s1, lm: mlndt_lm_s1}
//     compare_start_layers: {first: mlndt_lm_s1, second: mlndt_lm_s2}
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "registration/layouts/convergence_basin_analysis.hpp"
#include "registration/settings.hpp"
#include "sextant/eval/html_report.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {

struct BasinReportSettings {
  BasinCriterion criterion;
  double basin_rate = 0.5;
  double ndt_translation = 10, ndt_yaw = 5, ndt_settle = 25;
  double mlndt_translation = 25, mlndt_yaw = 15, mlndt_settle = 5;
  std::array<double, 2> translation_band{1.67, 3.75}, yaw_band{2.0, 4.5}, ndt_settle_band{12.5, 50.0};
  double solver_difference = 0.1;
  std::string newton, lm, first_layer, second_layer;  ///< method names (may be empty)
};

/// Reads `reference:` of a basin config (InputError with file, line, key).
BasinReportSettings read_basin_report_settings(const ExperimentConfig& config);

struct BasinData {
  const ExperimentConfig* config = nullptr;
  BasinReportSettings settings;
  std::vector<std::string> methods, scenes;
  std::vector<double> cell_edge;  ///< per scene [m]
  bool cells = true;              ///< offsets in NDT cell edges
  std::vector<BasinRun> runs;
  std::vector<double> offsets, yaws;  ///< distinct grid values
  /// Basin radius per method and scene: translation [offset unit] at yaw 0, yaw [deg] at offset 0.
  std::vector<std::vector<double>> translation, yaw;

  long method(const std::string& name) const;  ///< −1 when absent or without runs
  /// Success flags of methods a and b on the sweep points both ran (paired).
  void paired(std::size_t a, std::size_t b, std::vector<bool>& sa, std::vector<bool>& sb) const;
  /// A per-run quantity of a and b on the points where both succeeded (paired).
  void paired_values(std::size_t a, std::size_t b, double BasinRun::*field, std::vector<double>& va,
                     std::vector<double>& vb) const;
  std::vector<double> values(std::size_t m, double BasinRun::*field, bool successes_only) const;
  /// Scenes with runs (a profile may sweep a subset).
  std::vector<std::size_t> active_scenes() const;
  std::string offset_unit() const { return cells ? "NDT cells" : "m"; }
};

BasinData basin_data(const ExperimentConfig& config, const RegistrationParams& params,
                     const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);

/// Ratio of method p's median basin radius over the scenes to method b's (percentile bootstrap,
/// the scenes resampled); the same seed gives the claim's and the table's interval.
Interval basin_ratio(const BasinData& data, std::size_t p, std::size_t b, bool yaw);

/// The thesis' claims and the sanity checks, with verdicts from the statistical model.
std::vector<Claim> basin_claims(const BasinData& data, const RegistrationParams& params);

}  // namespace sextant
