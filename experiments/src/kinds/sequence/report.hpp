#pragma once
// The `sequence` kind's report sections, one file per layout in sequence/layouts/
// (dead_reckoning, kalman), and what they share: rows decoded into trajectories, errors, the
// trajectory figure, TUM files, the metrics table, the reference-block checks (named in the
// layout table, sequence/layouts/layouts.cpp).
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "kit/number_format.hpp"
#include "kit/row_codec.hpp"
#include "sequence/settings.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// ‖(x, y)_est − (x, y)_ref‖ per pose [m]: the 2D odometry has z = 0, so the comparison with it
/// is horizontal (the thesis' fig 5.15 plots the (x, y, z) norm).
std::vector<double> horizontal_errors(const PoseList& estimate, const PoseList& reference);
/// ‖p_est − p_ref‖ per pose [m].
std::vector<double> position_errors(const PoseList& estimate, const PoseList& reference);

/// One finished run, decoded into its trajectories.
struct TrajectoryRun {
  std::size_t method = 0;
  int repetition = 0;
  const RunRow* row = nullptr;
  PoseList truth, odometry, estimate, matcher;  ///< matcher: the KF layout's matcher alone
  std::vector<Eigen::Matrix3d> covariance;      ///< position block of P per scan (KF)
};

/// The runs with a usable row, in expansion order.
std::vector<TrajectoryRun> trajectory_runs(const std::vector<RunSpec>& runs,
                                           const std::vector<const RunRow*>& rows);

/// The runs of config method `method`, in expansion order.
std::vector<TrajectoryRun> runs_of_method(const std::vector<TrajectoryRun>& runs, std::size_t method);

/// Per-run values of one row key, in the order of `runs`.
std::vector<double> run_values(const std::vector<TrajectoryRun>& runs, const std::string& key);

/// Top-down trajectory figure of one run: truth, odometry, then the named estimates.
struct NamedPoses {
  NamedPoses(std::string name, const PoseList* poses, std::string color,
             std::vector<Eigen::Matrix3d> covariances = {}, double ellipse_sigma = 2)
      : name(std::move(name)),
        poses(poses),
        color(std::move(color)),
        covariances(std::move(covariances)),
        ellipse_sigma(ellipse_sigma) {}
  std::string name;
  const PoseList* poses;
  std::string color;
  std::vector<Eigen::Matrix3d> covariances;  ///< NaN entries draw no ellipse
  double ellipse_sigma;
};
ReportFigure trajectory_figure(const std::string& id, const std::string& caption, const std::string& title,
                               const TrajectoryRun& run, const std::vector<NamedPoses>& estimates);
/// Horizontal position error vs scan number for the odometry and the named estimates.
ReportFigure error_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const TrajectoryRun& run, const std::vector<NamedPoses>& estimates);

/// TUM files of one run's trajectories (stamp = scan index) for evo.
void add_tum_files(ReportSection& section, const TrajectoryRun& run, std::size_t first_scan,
                   const std::vector<NamedPoses>& trajectories);

/// A trajectory-metrics table: trajectory | end-point error xy, 3D | mean xy error | RPE over one scan
/// (mean, max translation; mean rotation) | KITTI drift, each the mean over the runs.
Table metrics_table(const std::string& caption, const std::string& label, std::size_t runs);
/// One row of that table for the trajectory `member` of every run.
void add_metric_rows(Table& table, const std::string& label, const std::vector<TrajectoryRun>& runs,
                     PoseList TrajectoryRun::*member);

/// Reference checks: each of `keys` is a number when given; `key` is [low, high] with low < high.
void check_numbers(SettingsReader& in, const std::vector<const char*>& keys);
void check_band(SettingsReader& in, const char* key);

}  // namespace sextant
