#pragma once
// A trajectory: poses (world ← body) with timestamps [s].
#include <vector>

#include <Eigen/Geometry>

namespace sextant {

struct StampedPose {
  double stamp = 0.0;  ///< time [s] (scan index when the source has no clock)
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

// C++17 aligned new makes Eigen's aligned_allocator unnecessary.
using Trajectory = std::vector<StampedPose>;

/// Relative motions between consecutive poses: result[i] = poses[i] ⊖ poses[i+1].
std::vector<Eigen::Isometry3d> consecutive_motions(const Trajectory& trajectory);

}  // namespace sextant
