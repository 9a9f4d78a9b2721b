#pragma once
// E1's numbers from the run rows (§5.1.1.1): success under the report's criterion, basin radii per
// method and scene, iterations until the pose settles, post-convergence jitter, and the
// per-layer normalised score curve. The layouts (registration_report_basin*.cpp) only format them.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// Success for the basin: ‖t(E)‖ < translation and angle(E) < rotation (both bounds, §5.1.1.1
/// states none; ours).
struct BasinCriterion {
  double max_translation_m = 0.5;
  double max_rotation_deg = 2.0;
  bool ok(double translation_m, double rotation_deg) const {
    return translation_m < max_translation_m && rotation_deg < max_rotation_deg;
  }
};

/// One registration as the basin layout reads it.
struct BasinRun {
  std::size_t method = 0, scene = 0;
  double offset = 0;  ///< sweep value [offset unit: NDT cells or m]
  double yaw = 0;     ///< |yaw| sweep value [deg]
  int direction = 0;  ///< 0..3 (registration/scenes.hpp)
  int repetition = 0;
  std::string point;  ///< sweep point and repetition: pairs the methods' runs
  bool success = false;
  double iterations = 0, seconds = 0;
  double settle = 0;     ///< iterations until the pose stays within the criterion (NaN if it never does)
  double jitter_cm = 0;  ///< mean translation change per iteration after settling [cm] (NaN: none)
  /// Iterations the run spent in its finest (last) layer until the solver stopped; for a
  /// single-grid NDT every iteration.
  double last_layer_iterations = 0;
  const RunRow* row = nullptr;
};

/// The error of every iterate against the truth: (translation [m], rotation [deg]); element 0 is
/// the initial guess (identity), then one per trace entry.
std::vector<std::pair<double, double>> iterate_errors(const RunRow& row);
/// First iterate index from which every later iterate meets the criterion; NaN when the last fails.
double settle_iteration(const std::vector<std::pair<double, double>>& errors, const BasinCriterion& c);
/// Iterations in the last layer the run iterated in (the trailing entries of the "layer" series
/// that equal its last; all of them for a single grid; the "iterations" value without the series).
/// ML-NDT's thesis preset runs a fixed three iterations in every coarser layer, so its total cannot
/// fall below the schedule whatever the solver does; this is the part the solver's stop decides.
double iterations_in_last_layer(const RunRow& row);
/// Mean ‖t_{k+1} − t_k‖ [cm] over the iterations after `settle` (0 when none follow; NaN if settle is).
double post_settle_jitter_cm(const RunRow& row, double settle);

std::vector<BasinRun> basin_runs(const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows,
                                 const BasinCriterion& criterion);

/// Sorted distinct values.
std::vector<double> distinct(std::vector<double> values);

/// Largest grid value r such that, at every grid value ≤ r, at least `rate` of the runs succeed
/// (`values` and `successes` per run); 0 when the smallest value already fails, NaN without runs.
double basin_radius(const std::vector<double>& values, const std::vector<bool>& successes, double rate);

/// Scores normalised per ML-NDT layer, (s − s_last) / (s_first − s_last) within each layer (scores of
/// different layers live on different grids, so one normalisation across layers is meaningless).
std::vector<double> normalise_per_layer(const std::vector<double>& score, const std::vector<double>& layer);

}  // namespace sextant
