#pragma once
// A trajectory on the ground plane (issue 22): each pose's x, y and heading, with its height, roll and
// pitch set to zero. A reference whose height and tilt cannot be trusted (a pose graph that spread a
// vertical correction over its keyframes, GNSS height) still judges the motion over the ground
// (docs/matcher_defaults.md, "The bias accrues per keyframe"). evo's `--project_to_plane xy` does the
// same for its metrics. Each trajectory is projected in its own world frame, so an estimate is aligned
// onto the reference first: projected unaligned, a trajectory that starts tilted in its world frame
// misjudges its motion over the ground.
//
//   const TrajectoryEvaluation e = evaluate_on_ground_plane(estimate, reference, settings);
#include <vector>

#include <Eigen/Geometry>

#include "sextant/eval/trajectory_evaluation.hpp"

namespace sextant {

/// `pose` (world ← body, z up) with its translation's x and y and the heading of its x axis in the
/// horizontal plane (atan2(R₁₀, R₀₀), the yaw of a yaw–pitch–roll decomposition R = Rz·Ry·Rx; the
/// thesis' eq. (3.8) composes Rx·Ry·Rz, whose yaw differs once roll and pitch are not small); z = 0 and
/// no roll or pitch. An x axis pointing straight up or down has no heading: the result is then the yaw
/// of 0.
Eigen::Isometry3d on_ground_plane(const Eigen::Isometry3d& pose);

/// Every pose of `poses` on the ground plane, in order.
std::vector<Eigen::Isometry3d> on_ground_plane(const std::vector<Eigen::Isometry3d>& poses);

/// evaluate_trajectory on the ground plane: `estimate` aligned onto `reference` in 3D by
/// settings.alignment (as evaluate_trajectory aligns it), then both on the ground plane, then every
/// metric there without a second alignment. The result's `ate.alignment` is the 3D one.
TrajectoryEvaluation evaluate_on_ground_plane(const PoseList& estimate, const PoseList& reference,
                                              const TrajectoryEvaluationSettings& settings);

}  // namespace sextant
