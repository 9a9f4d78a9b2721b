#include "simulation/room_sim_2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/filters/scan_matching_kf.hpp"

namespace sextant {
namespace {

/// Distance along the unit direction d from p (inside the room) to the first wall or circle.
double cast_ray(const RoomSim2dSettings& s, const Eigen::Vector2d& p, const Eigen::Vector2d& d) {
  const double hx = 0.5 * s.room_length, hy = 0.5 * s.room_width;
  double t = std::numeric_limits<double>::infinity();
  if (d.x() > 0) t = std::min(t, (hx - p.x()) / d.x());
  if (d.x() < 0) t = std::min(t, (-hx - p.x()) / d.x());
  if (d.y() > 0) t = std::min(t, (hy - p.y()) / d.y());
  if (d.y() < 0) t = std::min(t, (-hy - p.y()) / d.y());
  // Circle: |p + t d − c|² = r², first root in front of the ray.
  const Eigen::Vector2d o = p - Eigen::Vector2d(s.circle_x, s.circle_y);
  const double b = o.dot(d), c = o.squaredNorm() - s.circle_radius * s.circle_radius;
  const double disc = b * b - c;
  if (disc >= 0.0) {
    const double near = -b - std::sqrt(disc);
    if (near > 0.0) t = std::min(t, near);
  }
  return t;
}

/// The rectangle's corners counter-clockwise from the start (middle of the lower edge, heading
/// +x), then back to the start; `loops` times.
std::vector<Eigen::Vector2d> loop_waypoints(const RoomSim2dSettings& s) {
  const double hx = 0.5 * s.loop_length, hy = 0.5 * s.loop_width;
  const std::vector<Eigen::Vector2d> one = {{hx, -hy}, {hx, hy}, {-hx, hy}, {-hx, -hy}, {0.0, -hy}};
  std::vector<Eigen::Vector2d> all;
  for (int i = 0; i < s.loops; ++i) all.insert(all.end(), one.begin(), one.end());
  return all;
}

Eigen::Isometry3d planar_isometry(const Eigen::Vector3d& xi) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(xi[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(xi[0], xi[1], 0.0);
  return T;
}

Eigen::Vector3d planar_parameters(const Eigen::Isometry3d& T) {
  return {T.translation().x(), T.translation().y(), std::atan2(T.linear()(1, 0), T.linear()(0, 0))};
}

}  // namespace

bool RoomSim2dSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(room_length > 0 && room_width > 0 && circle_radius > 0))
    problem = "room_length, room_width and circle_radius must be > 0";
  else if (!(std::abs(circle_x) + circle_radius < 0.5 * room_length &&
             std::abs(circle_y) + circle_radius < 0.5 * room_width))
    problem = "the circle must lie inside the room";
  else if (!(loop_length > 0 && loop_width > 0 && loop_length < room_length && loop_width < room_width))
    problem = "the loop must be positive and smaller than the room";
  else if (beams < 8 || !(max_range > 0) || !(range_noise >= 0))
    problem = "beams >= 8, max_range > 0 and range_noise >= 0 required";
  else if (!(speed > 0 && dt > 0 && wheelbase > 0 && scan_every >= dt))
    problem = "speed, dt, wheelbase must be > 0 and scan_every >= dt";
  else if (!(max_steer > 0 && max_steer_rate > 0 && waypoint_radius > 0))
    problem = "max_steer, max_steer_rate and waypoint_radius must be > 0";
  else if (loops < 1 || max_steps < 1)
    problem = "loops and max_steps must be >= 1";
  else if (!(sigma_speed > 0 && sigma_steer > 0) || !std::isfinite(bias_speed) || !std::isfinite(bias_steer))
    problem = "sigma_speed and sigma_steer must be > 0, biases finite";
  else if (!(initial_sigma > 0 && measurement_noise_scale > 0))
    problem = "initial_sigma and measurement_noise_scale must be > 0";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

Eigen::Matrix2d RoomSim2dSettings::control_noise() const {
  return Eigen::Vector2d(sigma_speed * sigma_speed, sigma_steer * sigma_steer).asDiagonal();
}

MlndtSettings room_sim_matcher_settings() {
  MlndtSettings s;
  s.pyramid.layers = 3;
  std::string why;
  DofMask::from_names({"x", "y", "yaw"}, s.optimizer.dof, &why);
  return s;
}

PointCloud simulate_room_scan(const RoomSim2dSettings& s, const Eigen::Vector3d& pose, Rng& rng) {
  PointCloud cloud;
  cloud.reserve(static_cast<std::size_t>(s.beams));
  for (int i = 0; i < s.beams; ++i) {
    const double bearing = 2.0 * kPi * i / s.beams, a = pose[2] + bearing;
    const double range = cast_ray(s, pose.head<2>(), Eigen::Vector2d(std::cos(a), std::sin(a)));
    if (!(range <= s.max_range)) continue;
    const double r = range + s.range_noise * rng.normal();
    cloud.push_back(Eigen::Vector3f(static_cast<float>(r * std::cos(bearing)),
                                    static_cast<float>(r * std::sin(bearing)), 0.f));
  }
  return cloud;
}

std::string to_string(RoomSimStatus status) {
  switch (status) {
    case RoomSimStatus::kUpdated: return "updated";
    case RoomSimStatus::kMatcherFailed: return "matcher failed";
    case RoomSimStatus::kHessianNotPositive: return "hessian not positive definite";
    case RoomSimStatus::kSingularInnovation: return "singular innovation";
  }
  return "unknown";
}

std::vector<Eigen::Vector3d> RoomSim2dRun::truth() const {
  std::vector<Eigen::Vector3d> out;
  for (const auto& s : steps) out.push_back(s.truth);
  return out;
}
std::vector<Eigen::Vector3d> RoomSim2dRun::estimate() const {
  std::vector<Eigen::Vector3d> out;
  for (const auto& s : steps) out.push_back(s.estimate);
  return out;
}
std::vector<Eigen::Vector3d> RoomSim2dRun::odometry() const {
  std::vector<Eigen::Vector3d> out;
  for (const auto& s : steps) out.push_back(s.odometry);
  return out;
}

RoomSim2dRun run_room_sim_2d(const RoomSim2dSettings& s, Matcher& matcher, Rng& rng) {
  std::string why;
  if (!s.valid(&why)) throw std::invalid_argument("room simulation settings: " + why);
  const RangeBearingModel vehicle(s.model());
  const std::vector<Eigen::Vector2d> waypoints = loop_waypoints(s);
  const Eigen::Matrix2d Q = s.control_noise();

  Eigen::VectorXd truth = Eigen::Vector3d(0.0, -0.5 * s.loop_width, 0.0);
  Eigen::VectorXd odometry = truth;
  AckermannScanMatchingEkf ekf(s.model(), truth,
                               s.initial_sigma * s.initial_sigma * Eigen::Matrix3d::Identity());
  RoomSim2dRun run;
  RoomSimStep start;
  start.truth = start.estimate = start.odometry = truth;
  start.covariance = ekf.covariance();
  run.steps.push_back(start);

  // The reference scan is the scan of the last update (eq. 3.46 measures from its pose).
  PointCloud reference = simulate_room_scan(s, truth, rng);
  matcher.set_reference(reference);
  Eigen::Vector3d reference_truth = truth, reference_estimate = ekf.pose();

  const int scan_period = std::max(1, static_cast<int>(std::lround(s.scan_every / s.dt)));
  double steer = 0.0;
  std::size_t waypoint = 0;
  for (int k = 1; k <= s.max_steps && waypoint < waypoints.size(); ++k) {
    if ((waypoints[waypoint] - truth.head<2>()).norm() < s.waypoint_radius && ++waypoint == waypoints.size())
      break;
    const Eigen::Vector2d goal = waypoints[waypoint] - truth.head<2>();
    const double wanted =
        std::clamp(wrap_angle(std::atan2(goal.y(), goal.x()) - truth[2]), -s.max_steer, s.max_steer);
    const double max_change = s.max_steer_rate * s.dt;
    steer += std::clamp(wanted - steer, -max_change, max_change);
    truth = vehicle.process(truth, Eigen::Vector2d(s.speed, steer));  // eqs. (3.37)–(3.39)
    // Drawn last argument first: the order GCC gave these once-unsequenced draws (same data as before).
    const double steer_noise = rng.normal();
    const double speed_noise = rng.normal();
    const Eigen::Vector2d u(s.speed + s.bias_speed + s.sigma_speed * speed_noise,
                            steer + s.bias_steer + s.sigma_steer * steer_noise);
    odometry = vehicle.process(odometry, u);
    ekf.predict(u, Q);  // eqs. (3.48)–(3.49)
    ++run.controls;
    run.truth_path.push_back(truth);
    if (k % scan_period != 0) continue;

    RoomSimStep step;
    step.time = k * s.dt;
    step.truth = truth;
    step.odometry = odometry;
    step.xi_true = AckermannScanMatchingEkf::relative_measurement(reference_truth, truth);
    const PointCloud scan = simulate_room_scan(s, truth, rng);
    step.points = scan.size();
    // p_reference = T · p_scan, so T is the pose of the new scan in the reference frame (ξ).
    const Eigen::Vector3d guess =
        AckermannScanMatchingEkf::relative_measurement(reference_estimate, ekf.pose());
    const auto t0 = std::chrono::steady_clock::now();
    const RegistrationResult match = matcher.align(scan, planar_isometry(guess));
    step.match_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    step.iterations = match.iterations;
    step.xi_measured = planar_parameters(match.T);

    // eq. (3.50): R = H⁻¹ over the three free parameters (tx, ty, γ).
    const int active[3] = {0, 1, 5};
    Eigen::Matrix3d H;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) H(r, c) = match.H(active[r], active[c]);
    const Eigen::LLT<Eigen::Matrix3d> llt(0.5 * (H + H.transpose()));
    if (!match.converged) {
      step.status = RoomSimStatus::kMatcherFailed;
    } else if (!H.allFinite() || llt.info() != Eigen::Success) {
      step.status = RoomSimStatus::kHessianNotPositive;
    } else {
      step.R = s.measurement_noise_scale * llt.solve(Eigen::Matrix3d::Identity());
      if (ekf.update(step.xi_measured, step.R)) {  // eqs. (3.50)–(3.52)
        step.status = RoomSimStatus::kUpdated;
        ++run.updates;
        reference = scan;
        matcher.set_reference(reference);
        reference_truth = truth;
        reference_estimate = ekf.pose();
      } else {
        step.status = RoomSimStatus::kSingularInnovation;
      }
    }
    step.estimate = ekf.pose();
    step.covariance = ekf.covariance();
    run.steps.push_back(step);
  }
  return run;
}

}  // namespace sextant
