// The SE(3) exponential and logarithm in closed form (se3.hpp has the formulas and their source).
#include "sextant/core/se3.hpp"

#include <cmath>

namespace sextant {
namespace {

/// Below this angle [rad] the coefficients are their Taylor series to θ²: the next term is θ⁴ ≈ 1e-16.
constexpr double kSmallAngle = 1e-4;

Eigen::Matrix3d hat(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

/// (sin θ)/θ, (1 − cos θ)/θ², (θ − sin θ)/θ³.
struct ExpCoefficients {
  double a, b, c;
};

ExpCoefficients exp_coefficients(double theta) {
  const double t2 = theta * theta;
  if (theta < kSmallAngle) return {1.0 - t2 / 6.0, 0.5 - t2 / 24.0, 1.0 / 6.0 - t2 / 120.0};
  const double s = std::sin(theta), c = std::cos(theta);
  return {s / theta, (1.0 - c) / t2, (theta - s) / (t2 * theta)};
}

}  // namespace

Eigen::Isometry3d se3_exp(const Vector6d& twist) {
  const Eigen::Vector3d rho = twist.head<3>(), phi = twist.tail<3>();
  const double theta = phi.norm();
  const ExpCoefficients k = exp_coefficients(theta);
  const Eigen::Matrix3d P = hat(phi), P2 = P * P;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Matrix3d::Identity() + k.a * P + k.b * P2;
  T.translation() = (Eigen::Matrix3d::Identity() + k.b * P + k.c * P2) * rho;
  return T;
}

Vector6d se3_log(const Eigen::Isometry3d& T) {
  const Eigen::AngleAxisd rotation(Eigen::Matrix3d(T.linear()));
  const double theta = rotation.angle();  // in [0, π]
  const Eigen::Vector3d phi = theta * rotation.axis();
  const Eigen::Matrix3d P = hat(phi);
  // (1/θ²)·(1 − θ·sin θ / (2·(1 − cos θ))) → 1/12 + θ²/720 as θ → 0.
  const double d = theta < kSmallAngle
                       ? 1.0 / 12.0 + theta * theta / 720.0
                       : (1.0 - theta * std::sin(theta) / (2.0 * (1.0 - std::cos(theta)))) / (theta * theta);
  const Eigen::Matrix3d V_inverse = Eigen::Matrix3d::Identity() - 0.5 * P + d * P * P;
  Vector6d twist;
  twist.head<3>() = V_inverse * T.translation();
  twist.tail<3>() = phi;
  return twist;
}

Eigen::Isometry3d interpolate_motion(const Eigen::Isometry3d& T, double s) {
  return se3_exp(s * se3_log(T));
}

}  // namespace sextant
