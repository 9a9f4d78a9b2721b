#include "sextant/filters/plane_slam_model.hpp"

#include <cmath>

namespace sextant {
namespace {

Eigen::Matrix3d rot_x(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d rot_y(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d rot_z(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// d/dθ of the elementary rotations.
Eigen::Matrix3d drot_x(double a) {
  Eigen::Matrix3d d;
  d << 0, 0, 0, 0, -std::sin(a), -std::cos(a), 0, std::cos(a), -std::sin(a);
  return d;
}
Eigen::Matrix3d drot_y(double a) {
  Eigen::Matrix3d d;
  d << -std::sin(a), 0, std::cos(a), 0, 0, 0, -std::cos(a), 0, -std::sin(a);
  return d;
}
Eigen::Matrix3d drot_z(double a) {
  Eigen::Matrix3d d;
  d << -std::sin(a), -std::cos(a), 0, std::cos(a), -std::sin(a), 0, 0, 0, 0;
  return d;
}

Eigen::Matrix3d rotation_of(const Eigen::VectorXd& pose) {
  return rotation_from_euler(pose[3], pose[4], pose[5]);
}

// Columns (∂R/∂α)·v, (∂R/∂β)·v, (∂R/∂γ)·v (transposed derivatives when `transposed`).
Eigen::Matrix3d rotation_jacobian_times(const Eigen::VectorXd& pose, const Eigen::Vector3d& v,
                                        bool transposed) {
  const auto dR = rotation_derivatives(pose[3], pose[4], pose[5]);
  Eigen::Matrix3d J;
  for (int k = 0; k < 3; ++k)
    J.col(k) = transposed ? Eigen::Vector3d(dR[k].transpose() * v) : Eigen::Vector3d(dR[k] * v);
  return J;
}

}  // namespace

std::array<Eigen::Matrix3d, 3> rotation_derivatives(double alpha, double beta, double gamma) {
  return {drot_x(alpha) * rot_y(beta) * rot_z(gamma), rot_x(alpha) * drot_y(beta) * rot_z(gamma),
          rot_x(alpha) * rot_y(beta) * drot_z(gamma)};
}

// eq. (4.72)
Eigen::VectorXd PlaneSlamModel::process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const {
  Eigen::VectorXd next(6);
  next.head<3>() = pose.head<3>() + rotation_of(pose) * u.head<3>();
  for (int k = 3; k < 6; ++k) next[k] = wrap_angle(pose[k] + u[k]);
  return next;
}

Eigen::MatrixXd PlaneSlamModel::process_jacobian_pose(const Eigen::VectorXd& pose,
                                                      const Eigen::VectorXd& u) const {
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(6, 6);
  F.block<3, 3>(0, 3) = rotation_jacobian_times(pose, u.head<3>(), false);
  return F;
}

Eigen::MatrixXd PlaneSlamModel::process_jacobian_control(const Eigen::VectorXd& pose,
                                                         const Eigen::VectorXd& /*u*/) const {
  Eigen::MatrixXd G = Eigen::MatrixXd::Identity(6, 6);
  G.block<3, 3>(0, 0) = rotation_of(pose);
  return G;
}

// eq. (4.64), in the n·p = d sign convention.
Eigen::VectorXd PlaneSlamModel::observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& m) const {
  Eigen::VectorXd z(4);
  z.head<3>() = rotation_of(pose).transpose() * m.head<3>();
  z[3] = m[3] - m.head<3>().dot(pose.head<3>());
  return z;
}

Eigen::MatrixXd PlaneSlamModel::observe_jacobian_pose(const Eigen::VectorXd& pose,
                                                      const Eigen::VectorXd& m) const {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(4, 6);
  H.block<3, 3>(0, 3) = rotation_jacobian_times(pose, m.head<3>(), true);
  H.block<1, 3>(3, 0) = -m.head<3>().transpose();
  return H;
}

Eigen::MatrixXd PlaneSlamModel::observe_jacobian_landmark(const Eigen::VectorXd& pose,
                                                          const Eigen::VectorXd& /*m*/) const {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(4, 4);
  H.block<3, 3>(0, 0) = rotation_of(pose).transpose();
  H.block<1, 3>(3, 0) = -pose.head<3>().transpose();
  H(3, 3) = 1.0;
  return H;
}

// eqs. (4.57)–(4.58), in the n·p = d sign convention.
Eigen::VectorXd PlaneSlamModel::augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const {
  Eigen::VectorXd m(4);
  m.head<3>() = rotation_of(pose) * z.head<3>();
  m[3] = z[3] + m.head<3>().dot(pose.head<3>());
  return m;
}

Eigen::MatrixXd PlaneSlamModel::augment_jacobian_pose(const Eigen::VectorXd& pose,
                                                      const Eigen::VectorXd& z) const {
  const Eigen::Matrix3d dn = rotation_jacobian_times(pose, z.head<3>(), false);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(4, 6);
  G.block<3, 3>(0, 3) = dn;
  G.block<1, 3>(3, 0) = (rotation_of(pose) * z.head<3>()).transpose();
  G.block<1, 3>(3, 3) = pose.head<3>().transpose() * dn;
  return G;
}

Eigen::MatrixXd PlaneSlamModel::augment_jacobian_observation(const Eigen::VectorXd& pose,
                                                             const Eigen::VectorXd& /*z*/) const {
  const Eigen::Matrix3d R = rotation_of(pose);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(4, 4);
  G.block<3, 3>(0, 0) = R;
  G.block<1, 3>(3, 0) = pose.head<3>().transpose() * R;
  G(3, 3) = 1.0;
  return G;
}

Eigen::VectorXd PlaneSlamModel::align_observation(const Eigen::VectorXd& z,
                                                  const Eigen::VectorXd& predicted) const {
  return z.head<3>().dot(predicted.head<3>()) < 0.0 ? Eigen::VectorXd(-z) : z;
}

void PlaneSlamModel::normalize_landmark(Eigen::Ref<Eigen::VectorXd> m) const {
  const double norm = m.head<3>().norm();
  if (norm > 0.0 && std::isfinite(norm)) m /= norm;
}

Vector6d odometry_increment(const Pose6& from, const Pose6& to) {
  Vector6d u;
  const Eigen::Matrix3d R = rotation_from_euler(from.alpha, from.beta, from.gamma);
  u.head<3>() = R.transpose() * (Eigen::Vector3d(to.x, to.y, to.z) - Eigen::Vector3d(from.x, from.y, from.z));
  u[3] = wrap_angle(to.alpha - from.alpha);
  u[4] = wrap_angle(to.beta - from.beta);
  u[5] = wrap_angle(to.gamma - from.gamma);
  return u;
}

Eigen::Vector4d plane_vector(const Plane& plane) {
  Eigen::Vector4d v;
  v << plane.normal, plane.d;
  return v;
}

Plane plane_from_vector(const Eigen::Vector4d& v) {
  Plane p;
  p.normal = v.head<3>();
  p.d = v[3];
  return p;
}

}  // namespace sextant
