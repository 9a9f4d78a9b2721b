#pragma once
// The `plane_slam` kind's report: helpers shared by its layouts, one file per layout:
//   plane_slam/layouts/accuracy.cpp  — error norm per scan, maximum errors, NEES,
//                                     failures per P0 scale, the map with pose ellipses
//   plane_slam/layouts/seif.cpp      — update times against the map size, information images
//   plane_slam/layouts/benchmark.cpp — Wulf and Kümmerle per filter, spikes at loop closures
//   plane_slam/layouts/eseif.cpp     — ESEIF vs SEIF: NEES, update cost against the map, error
//   plane_slam/layouts/hybrid.cpp    — odometry- vs FbML-NDT-driven filters, accuracy and cost
//   plane_slam/layouts/fastslam.cpp  — accuracy, and the time per scan against the map size (E23)
// and the thesis' comparative claims declared in params.claims (plane_slam/claims.cpp).
// Each layout is one line in the table of plane_slam/layouts/layouts.cpp.
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "kit/number_format.hpp"
#include "kit/plane_slam_params.hpp"
#include "kit/row_groups.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/eval/verdict.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// The finished rows by method and sweep point: one MethodRows (kit/row_groups.hpp) per method
/// and p0_scale label ("" without a sweep), its rows by repetition; `ended` holds the runs that
/// ended as failed runs because the filter failed on most of its steps (slam_run_failure): no
/// trajectory to score, but a filter failure to count (E13's P0 study).
struct PlaneSlamRows {
  std::vector<std::string> points;  ///< sweep labels in config order ("" without a sweep)
  std::vector<MethodRows> groups;
  int repetitions = 1;
  const MethodRows* find(const std::string& method, const std::string& point) const;
  /// Groups of one sweep point, in method order.
  std::vector<const MethodRows*> at(const std::string& point) const;
};

PlaneSlamRows collect_plane_slam_rows(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                      const std::vector<const RunRow*>& rows);

/// Positions of a 6-per-scan pose series.
std::vector<Eigen::Vector3d> positions(const std::vector<double>& poses);
/// 0, 1, …, n−1.
std::vector<double> scan_axis(std::size_t n);
std::vector<std::size_t> scan_axis_indices(std::size_t n);
/// "p0_scale = 1000" or "" without a sweep.
std::string point_text(const std::string& point);
/// File-stem suffix for a sweep point ("" or "_p0_1000").
std::string point_stem(const std::string& point);
/// "true plane landmarks with true association" / "extracted planes with semantic association".
std::string landmark_text(const PlaneSlamParams& params);
/// The notes every layout starts with (landmarks, odometry, scans, repetitions, noise).
std::string common_notes(const ExperimentConfig& config, const PlaneSlamParams& params,
                         const PlaneSlamRows& data);
/// A reference number under reference[key][name], or nullopt.
std::optional<double> reference_value(const ExperimentConfig& config, const std::string& key,
                                      const std::string& name);

/// Error norm against the scan index for every method of a point and the odometry (figs 5.27–5.29);
/// `own_odometry` (method → model) adds the dead reckoning of each method-own odometry model.
ReportFigure error_figure(const PlaneSlamRows& data, const std::string& point, const std::string& series_name,
                          const std::string& odometry_series, const std::string& id,
                          const std::string& y_label, const std::string& caption,
                          const std::map<std::string, std::string>& own_odometry = {});
/// Top-down map (fig 5.30): true, estimated (with 2σ position ellipses) and odometry trajectories,
/// and the estimated planes (vertical ones as segments over their true extent when known).
ReportFigure map_figure(const ExperimentConfig& config, const PlaneSlamParams& params, const RunRow& row,
                        const std::string& method, const std::string& id);

/// How a per-scan time grows with the map: least-squares slope of `time` against
/// map_size over every repetition's scans (scan 0 left out: no motion update), with a bootstrap
/// interval; growth = slope · (map range) / median time (plane_slam/layouts/seif.cpp).
struct TimeGrowth {
  Interval slope;   ///< ms per landmark
  Interval growth;  ///< slope · (map range) / median time
  double median_ms = NAN;
  double map_lo = NAN, map_hi = NAN;
};
TimeGrowth time_growth(const MethodRows& g, const std::string& time, std::uint64_t seed);
/// "Flat" (a bounded cost, E17 and E22): the fitted time changes by less than this fraction of its
/// median across the map's range.
constexpr double kFlatGrowth = 0.5;
/// `time` per scan, or against the map size (repetition 1 of every method; log scale).
ReportFigure time_figure(const PlaneSlamRows& data, const std::string& time, const std::string& id,
                         const std::string& what, bool against_map);

/// Ω's block pattern of every information filter's first repetition, one image per map size asked for.
std::vector<ReportFigure> information_figures(const PlaneSlamRows& data);

/// Each method's sigma-point rule and parameters (kit/filter_parameters.hpp), when some method is a
/// sigma-point filter; nullopt otherwise.
std::optional<Table> plane_slam_sigma_point_table(const ExperimentConfig& config);
/// True when the thesis' numbers (config.reference) are for this sweep point: always without a
/// sweep; with one, only at reference.p0_scale (E13: the thesis gives maxima for P0 = 1e-6·I only).
bool reference_at_point(const ExperimentConfig& config, const std::string& point);

/// Sanity checks: every filter's maximum and final error below the odometry's (paired over repetitions).
std::vector<Claim> beats_odometry_claims(const PlaneSlamRows& data, std::uint64_t seed);

/// The claims of params.claims decided on the rows (plane_slam/claims.cpp).
std::vector<Claim> declared_claims(const ExperimentConfig& config, const PlaneSlamParams& params,
                                   const PlaneSlamRows& data);
void check_plane_slam_claims(const ExperimentConfig& config, const PlaneSlamParams& params);
/// The reference check every layout shares (named in plane_slam/layouts/layouts.cpp).
void check_plane_slam_reference(const ExperimentConfig& config);

}  // namespace sextant
