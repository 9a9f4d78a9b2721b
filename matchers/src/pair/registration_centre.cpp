#include "sextant/matchers/registration_centre.hpp"

namespace sextant {
namespace {

/// How far outside its box a scan's sensor may stand, as a fraction of the box's diagonal: a lidar
/// that sees only ahead stands its blind range (a metre or a few) before the box of what it sees,
/// tens of metres across. MulRan keyframes moved into their map frame 300 m away put the origin
/// 130 m outside a 300 m box: with half the diagonal as the margin, every step turned about it and
/// said degenerate.
constexpr double kSensorMargin = 0.1;

}  // namespace

Eigen::Vector3d registration_centre(const PointCloud& reference) {
  if (reference.empty()) return Eigen::Vector3d::Zero();
  const Bounds box = reference.bounds();
  const Eigen::Vector3d low = box.min.cast<double>(), high = box.max.cast<double>();
  const Eigen::Vector3d outside =
      low.cwiseMax(Eigen::Vector3d::Zero()) - high.cwiseMin(Eigen::Vector3d::Zero());
  if (!(outside.norm() > kSensorMargin * (high - low).norm())) return Eigen::Vector3d::Zero();
  return 0.5 * (low + high);
}

Matrix6d CentredFrame::hessian_in_coordinates(const Matrix6d& H_local, const Eigen::Isometry3d& T) const {
  if (!moved()) return H_local;
  // ∂(R·c)/∂(α, β, γ) by central differences of eq. (3.8): R is smooth, and a step of 1e-6 rad
  // leaves an error of order 1e-12·|c|.
  const Pose6 pose = to_pose6(T);
  constexpr double kStep = 1e-6;
  Matrix6d J = Matrix6d::Identity();
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d up(pose.alpha, pose.beta, pose.gamma), down = up;
    up(k) += kStep;
    down(k) -= kStep;
    J.block<3, 1>(0, 3 + k) = (rotation_from_euler(up(0), up(1), up(2)) * centre_ -
                               rotation_from_euler(down(0), down(1), down(2)) * centre_) /
                              (2.0 * kStep);
  }
  return J.transpose() * H_local * J;
}

}  // namespace sextant
