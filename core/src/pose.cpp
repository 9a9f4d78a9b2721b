#include "sextant/core/pose.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace sextant {

Vector6d Pose6::vector() const {
  Vector6d xi;
  xi << x, y, z, alpha, beta, gamma;
  return xi;
}

Pose6 Pose6::from_vector(const Vector6d& xi) {
  return {xi[0], xi[1], xi[2], xi[3], xi[4], xi[5]};
}

double wrap_angle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [−π, π]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

// eq. (3.8)
Eigen::Matrix3d rotation_from_euler(double alpha, double beta, double gamma) {
  return (Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(gamma, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// R = Rx·Ry·Rz has R(0,2) = sβ, R(1,2) = −sα·cβ, R(2,2) = cα·cβ, R(0,0) = cβ·cγ, R(0,1) = −cβ·sγ.
Eigen::Vector3d euler_from_rotation(const Eigen::Matrix3d& R) {
  const double cos_beta = std::hypot(R(0, 0), R(0, 1));
  const double beta = std::atan2(R(0, 2), cos_beta);
  if (cos_beta < 1e-6) {
    // Gimbal lock: Ry(±π/2)·Rz(γ) = Rx(±γ)·Ry(±π/2), so only α ± γ is observable; put it into α.
    return {std::atan2(R(2, 1), R(1, 1)), beta, 0.0};
  }
  return {std::atan2(-R(1, 2), R(2, 2)), beta, std::atan2(-R(0, 1), R(0, 0))};
}

Eigen::Isometry3d to_isometry(const Pose6& pose) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotation_from_euler(pose.alpha, pose.beta, pose.gamma);
  T.translation() = Eigen::Vector3d(pose.x, pose.y, pose.z);
  return T;
}

Pose6 to_pose6(const Eigen::Isometry3d& T) {
  const Eigen::Vector3d angles = euler_from_rotation(T.linear());
  const Eigen::Vector3d t = T.translation();
  return {t.x(), t.y(), t.z(), angles[0], angles[1], angles[2]};
}

Eigen::Isometry3d compose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return a * b;
}

Eigen::Isometry3d inverse(const Eigen::Isometry3d& T) {
  Eigen::Isometry3d inv = Eigen::Isometry3d::Identity();
  inv.linear() = T.linear().transpose();
  inv.translation() = -(T.linear().transpose() * T.translation());
  return inv;
}

Eigen::Isometry3d relative(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return inverse(a) * b;
}

double rotation_angle(const Eigen::Isometry3d& T) {
  // atan2(sin θ, cos θ) with sin θ from the skew part of R and cos θ from its trace: exact for small
  // angles too, where acos((tr R − 1) / 2) cannot resolve anything below about 1.5e-8 rad.
  const Eigen::Matrix3d& R = T.linear();
  const double sin_angle =
      0.5 * Eigen::Vector3d(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1)).norm();
  const double cos_angle = (R.trace() - 1.0) / 2.0;
  return std::atan2(sin_angle, cos_angle);
}

double translation_norm(const Eigen::Isometry3d& T) {
  return T.translation().norm();
}

bool is_finite(const Eigen::Isometry3d& T) {
  return T.matrix().allFinite();
}

bool is_finite(const Pose6& pose) {
  return pose.vector().allFinite();
}

}  // namespace sextant

namespace sextant {

std::string rigid_problem(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double tolerance) {
  if (!R.allFinite() || !t.allFinite()) return "not finite";
  const double off = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (off > tolerance) {
    std::ostringstream out;
    out << "the rotation is not orthonormal (max |RᵀR − I| = " << std::setprecision(3) << off
        << ", tolerance " << tolerance << ")";
    return out.str();
  }
  if (R.determinant() <= 0.0) return "the rotation is a reflection (det R < 0)";
  return {};
}

Eigen::Isometry3d scale_motion(const Eigen::Isometry3d& T, double factor) {
  const Eigen::AngleAxisd rotation(T.rotation());
  Eigen::Isometry3d scaled = Eigen::Isometry3d::Identity();
  scaled.linear() = Eigen::AngleAxisd(rotation.angle() * factor, rotation.axis()).toRotationMatrix();
  scaled.translation() = T.translation() * factor;
  return scaled;
}

}  // namespace sextant
