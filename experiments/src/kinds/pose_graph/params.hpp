#pragma once
// The `pose_graph` kind's view of an experiment config (thesis §7.2 future work): chained
// scan-matching odometry over the campus, a pose graph over it with verified loop closures, and
// the plane-SLAM filters over the same scans for comparison.
//
//   methods:
//     - {name: mlndt, matcher: mlndt, settings: {...}, sampler: gbs,  # odometry + loop closures + graph
//        closure_settings: {wide_basin: {}}}    # the closures' matcher settings (default: settings)
//     - {name: ekf, filter: ekf}                                      # plane_slam methods
//     - {name: ukf, filter: ukf, scans: 150}                          # … may stop early
//   params:
//     scans: 468                  # the first N scans of the campus (0: all)
//     odometry: resample          # registrations' guesses: campus odometry, or redrawn per run
//                                 #   from the campus' odometry model (the filters' draw, same seed)
//     guess: odometry             # odometry | constant_velocity | identity (run_odometry)
//     loop_closure: {radius: 10, min_index_gap: 30, min_path_gap: 60, stride: 4,
//                    max_mean_score: 6, min_matched_fraction: 0.5, max_correction_m: 8,
//                    max_correction_deg: 20, information_scale: 1}     # loop_closure.hpp
//     closure_rounds: 2          # candidates along the chain, then along the graph solved so far
//     calibrate_information: true   # odometry and closure Ω rescaled by variance component estimation
//     graph: {loss: cauchy, loss_scale: 3, max_iterations: 100}      # pose_graph.hpp
//     false_closures: 1           # injected "same place" closures between far-apart poses
//     false_closure_min_distance: 40   # [m] true distance between the poses a false closure joins
//     batch_scans: 20             # the claims' bootstrap resamples batch means over this many scans
//     false_closure_tolerance_m: 0.5   # "not wrecked": mean error up by less than this [m]
//     solve_budget: 0.1           # "cheap": the graph solve under this fraction of the registrations' time
//     filters: {landmarks: true, min_points: 300, odometry: resample, slam: {...}}  # plane_slam keys
#include <cstddef>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "kit/plane_slam_params.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/matchers/matcher_spec.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/posegraph/loop_closure.hpp"
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {

struct PoseGraphParams {
  std::size_t scans = 0;  ///< 0: every scan of the campus
  OdometrySource odometry = OdometrySource::kResample;
  OdometryGuess guess = OdometryGuess::odometry;
  LoopClosureSettings loop_closure;
  /// Rescale the odometry and closure Ω by their variance components (posegraph/variance_components.hpp)
  bool calibrate_information = true;
  std::size_t closure_rounds = 2;  ///< candidate searches: along the chain, then along each solved graph
  PoseGraphSettings graph;
  std::size_t false_closures = 1;
  double false_closure_min_distance = 40.0;
  std::size_t batch_scans = 20;
  double false_closure_tolerance_m = 0.5;
  double solve_budget = 0.1;
  PlaneSlamParams filters;  ///< the filter methods' params (plane_slam kind)
};

/// A method: the odometry + pose graph pipeline (`matcher:`) or a plane-SLAM filter (`filter:`).
struct PoseGraphMethod {
  std::string name;
  bool is_filter = false;
  RegistrationSpec odometry;  ///< when !is_filter
  /// The loop-closure registrations' matcher (`closure_settings`, else the odometry's), on its sampler
  MatcherSpec closure;
  PlaneSlamMethod filter;  ///< when is_filter
};

/// Reads and checks `params` (InputError with file, line, key).
PoseGraphParams read_pose_graph_params(const ExperimentConfig& config);
std::vector<PoseGraphMethod> read_pose_graph_methods(const ExperimentConfig& config);

}  // namespace sextant
