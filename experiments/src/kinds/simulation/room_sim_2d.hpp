#pragma once
// The 2D scan-matching simulation of §5.1.3.1 (E8, figs 5.16–5.18): a rectangular room with a
// circle inside, a 360° range scanner, and an Ackermann vehicle (eqs. 3.37–3.39) that drives a
// rectangular loop around the circle `loops` times. The vehicle's controls reach the filter
// with noise (and an optional bias); every `scan_every` seconds the new scan is matched
// against the scan of the last update by a matcher restricted to x, y, yaw (the `dof: [x, y,
// yaw]` mask; the scans are points with z = 0, which the ML-NDT layer grid handles by leaving
// the zero-extent axis out of the cell volume). The match gives ξ = (t_x, t_y, γ) (eq. 3.46)
// with R = inverse of the matcher's Hessian restricted to x, y, yaw (eq. 3.50), fed to
// AckermannScanMatchingEkf (eqs. 3.48–3.52).
//
//   RoomSim2dSettings s;                      // or read_room_sim_2d_settings (room_sim_2d_settings.hpp)
//   MlndtMatcher matcher(room_sim_matcher_settings());
//   Rng rng(seed);
//   RoomSim2dRun run = run_room_sim_2d(s, *matcher, rng);
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant {

struct RoomSim2dSettings {
  // World: the room is centred at the origin.
  double room_length = 20.0;   ///< extent along x [m]
  double room_width = 14.0;    ///< extent along y [m]
  double circle_x = 0.0;       ///< centre of the circle [m]
  double circle_y = 0.0;       ///< [m]
  double circle_radius = 1.5;  ///< [m]
  // Scanner (360°, beams evenly spaced from the heading).
  int beams = 360;            ///< rays per scan [count]
  double max_range = 30.0;    ///< no return beyond this [m]
  double range_noise = 0.01;  ///< σ of the Gaussian range noise [m]
  double scan_every = 1.0;    ///< time between scans [s]
  // Vehicle (Ackermann, eqs. 3.37–3.39) and its loop.
  double speed = 2.0;            ///< V [m/s]
  double dt = 0.1;               ///< control period [s]
  double wheelbase = 1.5;        ///< L [m]
  double max_steer = 0.5236;     ///< steering limit [rad] (30°)
  double max_steer_rate = 0.6;   ///< steering rate limit [rad/s]
  double loop_length = 10.0;     ///< waypoint rectangle along x, centred at the origin [m]
  double loop_width = 6.0;       ///< waypoint rectangle along y [m]
  double waypoint_radius = 1.0;  ///< a waypoint counts as reached within this distance [m]
  int loops = 2;                 ///< times the loop is driven (thesis: two) [count]
  int max_steps = 5000;          ///< cap on controls [count]
  // Odometry: the controls the filter sees.
  double sigma_speed = 0.1;    ///< σ of the speed noise [m/s]
  double sigma_steer = 0.035;  ///< σ of the steering noise [rad] (2°)
  double bias_speed = 0.0;     ///< constant speed error [m/s]
  double bias_steer = 0.01;    ///< constant steering error [rad]
  // Filter.
  double initial_sigma = 0.01;           ///< P0 = σ² I (the start pose is known) [m, rad]
  double measurement_noise_scale = 1.0;  ///< R = scale · H⁻¹ (eq. 3.50 is scale 1) [-]

  bool valid(std::string* why) const;
  RangeBearingModelSettings model() const { return {dt, wheelbase}; }
  Eigen::Matrix2d control_noise() const;  ///< Q = diag(σ_V², σ_γ²) (biases are unknown to it)
};

/// The ML-NDT settings the simulation needs by default: the library's defaults with x, y, yaw free
/// and three layers (the fourth layer's cells hold too few points of a few hundred beams); as YAML:
/// room_sim_matcher_defaults() of room_sim_2d_settings.hpp.
MlndtSettings room_sim_matcher_settings();

/// One range scan at `pose` (x, y, heading) in the sensor frame, points with z = 0. Beams with
/// no return within max_range are dropped.
PointCloud simulate_room_scan(const RoomSim2dSettings& settings, const Eigen::Vector3d& pose, Rng& rng);

enum class RoomSimStatus {
  kUpdated,             ///< the match updated the EKF
  kMatcherFailed,       ///< the matcher did not converge; prediction kept
  kHessianNotPositive,  ///< H restricted to x, y, yaw is not positive definite; prediction kept
  kSingularInnovation,  ///< the EKF refused the update; prediction kept
};
std::string to_string(RoomSimStatus status);

/// One scan (one measurement step).
struct RoomSimStep {
  double time = 0.0;                                      ///< [s]
  Eigen::Vector3d truth = Eigen::Vector3d::Zero();        ///< true pose (x, y, heading)
  Eigen::Vector3d estimate = Eigen::Vector3d::Zero();     ///< EKF pose after the step
  Eigen::Vector3d odometry = Eigen::Vector3d::Zero();     ///< dead reckoning of the noisy controls
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();   ///< EKF covariance after the step
  Eigen::Vector3d xi_true = Eigen::Vector3d::Zero();      ///< true ξ from the reference scan (eq. 3.46)
  Eigen::Vector3d xi_measured = Eigen::Vector3d::Zero();  ///< the matcher's ξ
  Eigen::Matrix3d R = Eigen::Matrix3d::Zero();            ///< H⁻¹ restricted to x, y, yaw (scaled)
  RoomSimStatus status = RoomSimStatus::kUpdated;
  int iterations = 0;          ///< matcher iterations
  std::size_t points = 0;      ///< points in the scan
  double match_seconds = 0.0;  ///< wall time of the match
};

struct RoomSim2dRun {
  std::vector<RoomSimStep> steps;  ///< one per scan; element 0 is the start (no match)
  std::size_t controls = 0;        ///< control periods simulated
  /// The true pose after every control (time (k + 1)·dt), for measurements between scans (the lag).
  std::vector<Eigen::Vector3d> truth_path;
  std::size_t updates = 0;  ///< steps with status kUpdated
  std::vector<Eigen::Vector3d> truth() const;
  std::vector<Eigen::Vector3d> estimate() const;
  std::vector<Eigen::Vector3d> odometry() const;
};

/// Drives the loops, scanning and matching every scan_every seconds. Throws
/// std::invalid_argument when the settings are not valid.
RoomSim2dRun run_room_sim_2d(const RoomSim2dSettings& settings, Matcher& matcher, Rng& rng);

}  // namespace sextant
