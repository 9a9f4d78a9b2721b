// A trajectory on the ground plane (ground_plane.hpp).
#include "sextant/eval/ground_plane.hpp"

#include <cmath>

namespace sextant {

Eigen::Isometry3d on_ground_plane(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& R = pose.linear();
  const double heading = std::atan2(R(1, 0), R(0, 0));  // atan2(0, 0) = 0
  Eigen::Isometry3d flat = Eigen::Isometry3d::Identity();
  flat.linear() = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  flat.translation() = Eigen::Vector3d(pose.translation().x(), pose.translation().y(), 0.0);
  return flat;
}

std::vector<Eigen::Isometry3d> on_ground_plane(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Isometry3d> flat;
  flat.reserve(poses.size());
  for (const Eigen::Isometry3d& pose : poses) flat.push_back(on_ground_plane(pose));
  return flat;
}

TrajectoryEvaluation evaluate_on_ground_plane(const PoseList& estimate, const PoseList& reference,
                                              const TrajectoryEvaluationSettings& settings) {
  const TrajectoryEvaluation in_3d = evaluate_trajectory(estimate, reference, settings);
  if (!in_3d.status.ok) return in_3d;
  // Aligned once, in 3D, then projected (evo's order): a second alignment on the plane would change
  // the ATE only, and the alignment reported is the one that was applied.
  TrajectoryEvaluationSettings projected = settings;
  projected.alignment = Alignment::none;
  TrajectoryEvaluation flat =
      evaluate_trajectory(on_ground_plane(in_3d.aligned_estimate), on_ground_plane(reference), projected);
  flat.ate.alignment = in_3d.ate.alignment;
  flat.ate.roll_from_orientations = in_3d.ate.roll_from_orientations;
  return flat;
}

}  // namespace sextant
