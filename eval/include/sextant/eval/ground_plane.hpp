#pragma once
// A trajectory on the ground plane (issue 22): each pose's x, y and heading, with its height, roll and
// pitch set to zero. A reference whose height and tilt cannot be trusted (a pose graph that spread a
// vertical correction over its keyframes, GNSS height) still judges the motion over the ground: MulRan
// Riverside02's reference pitches 0.06° per keyframe against every lidar odometry of its keyframes, its
// own included (docs/matcher_defaults.md, "The bias accrues per keyframe"). evo's `--project_to_plane
// xy` does the same for its metrics.
//
//   const PoseList flat = on_ground_plane(poses);  // then any metric of trajectory_metrics.hpp
#include <vector>

#include <Eigen/Geometry>

namespace sextant {

/// `pose` (world ← body, z up) with its translation's x and y and the heading of its x axis in the
/// horizontal plane (atan2(R₁₀, R₀₀), the yaw of eq. (3.8)'s decomposition when roll and pitch are
/// small); z = 0 and no roll or pitch. An x axis pointing straight up or down has no heading: the
/// result is then the yaw of 0.
Eigen::Isometry3d on_ground_plane(const Eigen::Isometry3d& pose);

/// Every pose of `poses` on the ground plane, in order.
std::vector<Eigen::Isometry3d> on_ground_plane(const std::vector<Eigen::Isometry3d>& poses);

}  // namespace sextant
