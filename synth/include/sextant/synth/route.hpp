#pragma once
// The campus trajectory: a route of straight legs and rounded corners (arcs, or with
// trajectory.corner_transition clothoids easing each arc in and out) along the roads of the
// 2×2 blocks, four loops that come back to early places (near 15 %, 50 %, 70–75 % and the
// end), one turn on the spot of `sharp_turn_deg` between scans 3 and 4, and a ground-following
// 6D pose (z, roll and pitch from the terrain) at each stop-and-go scan position.
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth {

/// A planar position with its heading (travel direction, counter-clockwise from +x) [m, rad].
struct RoutePoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double heading = 0.0;
};

/// How far before its vertex a corner of `turn` [rad] starts (and after it ends) [m]: R tan(θ / 2) for an
/// arc of `radius` R; with a `transition` Ls > 0, clothoids of Ls (≤ R θ) easing the arc in and out, the
/// road engineer's (R + p) tan(θ / 2) + k, with the arc's shift p and the clothoid's start k before it.
double corner_tangent_length(double radius, double transition, double turn);

/// Length of the approach leg before the sharp turn for `scans` poses [m]; the world keeps
/// the west border clear of it.
double start_leg_length(const WorldSettings& world, const TrajectorySettings& trajectory);

/// `trajectory.scans` stop-and-go positions, equally spaced along the route.
std::vector<RoutePoint> sample_route(const WorldSettings& world, const TrajectorySettings& trajectory,
                                     Rng& rng);

/// World ← sensor pose standing on the ground at a route point (z, roll, pitch follow the terrain).
Eigen::Isometry3d ground_following_pose(const World& world, const TrajectorySettings& trajectory,
                                        const RoutePoint& point);

/// The sensor's turn, for a hand-held platform, at scan `index` of the route: a yaw swing of
/// look_around_deg about the heading with a period of look_around_scans (the person looks around: at most
/// 2π · look_around_deg / look_around_scans per scan, 11° with the defaults), and a sway in roll and
/// pitch of sway_deg over periods of 5.3 and 7.1 scans (the gait), applied in the sensor's frame. The
/// identity for a car.
Eigen::Matrix3d handheld_sway(const TrajectorySettings& trajectory, std::size_t index);

}  // namespace sextant::synth
