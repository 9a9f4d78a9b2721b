#include "sextant/filters/relative_motion.hpp"

#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {
namespace {

/// δo = euler(R(o)·R(a)) − o, wrapped (the header's derivation).
Eigen::Vector3d angle_increment(const Vector6d& from, const Eigen::Vector3d& a) {
  const Eigen::Matrix3d R =
      rotation_from_euler(from[3], from[4], from[5]) * rotation_from_euler(a[0], a[1], a[2]);
  const Eigen::Vector3d to = euler_from_rotation(R);
  return Eigen::Vector3d(wrap_angle(to[0] - from[3]), wrap_angle(to[1] - from[4]),
                         wrap_angle(to[2] - from[5]));
}

}  // namespace

Matrix6d relative_pose_jacobian(const Vector6d& from, const Vector6d& relative) {
  Matrix6d J = Matrix6d::Zero();
  J.topLeftCorner<3, 3>().setIdentity();
  constexpr double h = 1e-6;
  const Eigen::Vector3d a = relative.tail<3>();
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = a, minus = a;
    plus[k] += h;
    minus[k] -= h;
    const Eigen::Vector3d d = angle_increment(from, plus) - angle_increment(from, minus);
    for (int i = 0; i < 3; ++i) J(3 + i, 3 + k) = wrap_angle(d[i]) / (2.0 * h);
  }
  return J;
}

MotionIncrement increment_from_relative_pose(const Vector6d& from, const Eigen::Isometry3d& relative,
                                             const Matrix6d& covariance) {
  const Vector6d p = to_pose6(relative).vector();
  MotionIncrement m;
  m.u.head<3>() = relative.translation();
  m.u.tail<3>() = angle_increment(from, p.tail<3>());
  const Matrix6d J = relative_pose_jacobian(from, p);
  m.Q = J * covariance * J.transpose();
  m.Q = 0.5 * (m.Q + m.Q.transpose());
  return m;
}

}  // namespace sextant
