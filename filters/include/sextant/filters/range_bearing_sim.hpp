#pragma once
// The 2D range–bearing point-landmark simulator of §5.2.1.3 A (eqs. 5.7–5.9): an Ackermann
// vehicle at constant speed steers through waypoints; controls reach the filter with noise
// (1 m/s, 1°), landmarks within range are observed every 2.5 s with noise (1 m, 1°). Known
// data association (landmark ids). Used by the UKF-vs-RSPKF Monte Carlo (E15) and the NEES tests.
#include <vector>

#include <Eigen/Core>

#include "sextant/core/rng.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/slam_runner.hpp"

namespace sextant {

struct RangeBearingSimSettings {
  double speed = 2.0;               ///< V [m/s]
  double dt = 0.05;                 ///< control period [s]
  double wheelbase = 4.0;           ///< L [m]
  double max_steer = 0.5236;        ///< steering limit [rad] (30°)
  double max_steer_rate = 0.3491;   ///< steering rate limit [rad/s] (20°/s)
  double observe_every = 2.5;       ///< time between observations [s]
  double max_range = 30.0;          ///< sensor range [m]
  double sigma_speed = 1.0;         ///< control noise on V [m/s, (0, 10·speed)]
  double sigma_steer = 0.017453;    ///< control noise on the steering angle [rad (1°), (0, π/2)]
  double sigma_range = 1.0;         ///< range noise [m, (0, max_range)]
  double sigma_bearing = 0.017453;  ///< bearing noise [rad (1°), (0, π/2)]
  double waypoint_radius = 2.0;     ///< a waypoint is reached within this distance [m]
  int max_steps = 2000;             ///< stop after this many controls even if waypoints remain
  bool valid(std::string* why) const;
  RangeBearingModelSettings model() const { return {dt, wheelbase}; }
  Eigen::Matrix2d control_noise() const;      ///< Q = diag(σ_V², σ_γ²)
  Eigen::Matrix2d observation_noise() const;  ///< R = diag(σ_r², σ_b²)
};

struct RangeBearingWorld {
  std::vector<Eigen::Vector2d> landmarks;
  std::vector<Eigen::Vector2d> waypoints;  ///< visited in order, starting from the origin heading +x
};

/// A square loop of side `side` metres with `landmarks` landmarks scattered near its edges.
RangeBearingWorld make_range_bearing_world(int landmarks, double side, Rng& rng);

struct RangeBearingRun {
  std::vector<SlamStepInput> steps;         ///< noisy controls and observations for the filter
  std::vector<Eigen::Vector3d> true_poses;  ///< ground truth after each step
};

RangeBearingRun simulate_range_bearing(const RangeBearingWorld& world,
                                       const RangeBearingSimSettings& settings, Rng& rng);

}  // namespace sextant
