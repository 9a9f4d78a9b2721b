#include "sextant/filters/range_bearing_sim.hpp"

#include <algorithm>
#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant {

bool RangeBearingSimSettings::valid(std::string* why) const {
  if (!(speed > 0 && dt > 0 && wheelbase > 0)) return *why = "speed, dt and wheelbase must be > 0", false;
  if (!(max_steer > 0 && max_steer_rate > 0)) return *why = "steering limits must be > 0", false;
  if (!(observe_every >= dt && max_range > 0))
    return *why = "observe_every must be >= dt, max_range > 0", false;
  if (!(sigma_speed > 0 && sigma_steer > 0 && sigma_range > 0 && sigma_bearing > 0))
    return *why = "noise standard deviations must be > 0", false;
  // Physical bounds: a noise as large as what it measures leaves nothing to estimate.
  if (!(sigma_range < max_range)) return *why = "sigma_range must be < max_range (the sensor's reach)", false;
  if (!(sigma_bearing < kPi / 2)) return *why = "sigma_bearing must be < π/2 rad (90°)", false;
  if (!(sigma_speed < 10 * speed)) return *why = "sigma_speed must be < 10 × speed", false;
  if (!(sigma_steer < kPi / 2)) return *why = "sigma_steer must be < π/2 rad (90°)", false;
  if (!(waypoint_radius > 0) || max_steps < 1) return *why = "waypoint_radius > 0 and max_steps >= 1", false;
  return true;
}

Eigen::Matrix2d RangeBearingSimSettings::control_noise() const {
  return Eigen::Vector2d(sigma_speed * sigma_speed, sigma_steer * sigma_steer).asDiagonal();
}

Eigen::Matrix2d RangeBearingSimSettings::observation_noise() const {
  return Eigen::Vector2d(sigma_range * sigma_range, sigma_bearing * sigma_bearing).asDiagonal();
}

RangeBearingWorld make_range_bearing_world(int landmarks, double side, Rng& rng) {
  RangeBearingWorld world;
  world.waypoints = {{side, 0.0}, {side, side}, {0.0, side}, {0.0, 0.0}};
  for (int i = 0; i < landmarks; ++i) {
    const double along = rng.uniform(0.0, 4.0 * side);
    const int edge = std::min(3, static_cast<int>(along / side));
    const double s = along - edge * side, offset = rng.uniform(-8.0, 8.0);
    const Eigen::Vector2d corners[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    const Eigen::Vector2d a = corners[edge], b = corners[(edge + 1) % 4];
    const Eigen::Vector2d dir = (b - a).normalized(), normal(-dir.y(), dir.x());
    world.landmarks.push_back(a + s * dir + offset * normal);
  }
  return world;
}

RangeBearingRun simulate_range_bearing(const RangeBearingWorld& world, const RangeBearingSimSettings& s,
                                       Rng& rng) {
  const RangeBearingModel model(s.model());
  RangeBearingRun run;
  Eigen::VectorXd pose = Eigen::VectorXd::Zero(3);
  double steer = 0.0;
  std::size_t waypoint = 0;
  const int observe_period = std::max(1, static_cast<int>(std::lround(s.observe_every / s.dt)));
  for (int k = 1; k <= s.max_steps && waypoint < world.waypoints.size(); ++k) {
    const Eigen::Vector2d to_goal = world.waypoints[waypoint] - pose.head<2>();
    if (to_goal.norm() < s.waypoint_radius && ++waypoint == world.waypoints.size()) break;
    const Eigen::Vector2d goal =
        world.waypoints[std::min(waypoint, world.waypoints.size() - 1)] - pose.head<2>();
    const double wanted =
        std::clamp(wrap_angle(std::atan2(goal.y(), goal.x()) - pose[2]), -s.max_steer, s.max_steer);
    const double max_change = s.max_steer_rate * s.dt;
    steer += std::clamp(wanted - steer, -max_change, max_change);
    const Eigen::Vector2d u_true(s.speed, steer);
    pose = model.process(pose, u_true);  // eq. (5.7)

    SlamStepInput step;
    // Drawn last argument first: the order GCC gave these once-unsequenced draws (same data as before).
    const double steer_noise = rng.normal();
    const double speed_noise = rng.normal();
    step.u = Eigen::Vector2d(s.speed + s.sigma_speed * speed_noise, steer + s.sigma_steer * steer_noise);
    if (k % observe_period == 0) {
      for (std::size_t i = 0; i < world.landmarks.size(); ++i) {
        Eigen::VectorXd z = model.observe(pose, world.landmarks[i]);  // eq. (5.8)
        if (z[0] > s.max_range) continue;
        z[0] += s.sigma_range * rng.normal();
        z[1] = wrap_angle(z[1] + s.sigma_bearing * rng.normal());
        step.observations.push_back({z, static_cast<int>(i)});
      }
    }
    run.steps.push_back(std::move(step));
    run.true_poses.push_back(pose.head<3>());
  }
  return run;
}

}  // namespace sextant
