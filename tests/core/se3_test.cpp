// The closed-form SE(3) exponential and logarithm (se3.hpp) against a direct computation: the matrix
// exponential and logarithm of the 4×4 twist matrix [Φ ρ; 0 0] by Eigen's general algorithms
// (unsupported/MatrixFunctions: Padé approximants with scaling and squaring), which know nothing of
// rotations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <unsupported/Eigen/MatrixFunctions>

#include "sextant/core/se3.hpp"

namespace sextant {
namespace {

Eigen::Matrix4d twist_matrix(const Vector6d& xi) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 1) = -xi[5], m(0, 2) = xi[4], m(1, 0) = xi[5], m(1, 2) = -xi[3], m(2, 0) = -xi[4], m(2, 1) = xi[3];
  m.block<3, 1>(0, 3) = xi.head<3>();
  return m;
}

Vector6d twist(double tx, double ty, double tz, double rx, double ry, double rz) {
  Vector6d xi;
  xi << tx, ty, tz, rx, ry, rz;
  return xi;
}

/// Rotation vectors from nothing, through a lidar step's few degrees, to nearly a half turn.
std::vector<Vector6d> twists() {
  return {twist(1.0, -0.2, 0.05, 0.0, 0.0, 0.0), twist(0.3, 0.1, -0.4, 1e-9, -2e-9, 3e-9),
          twist(1.0, 0.0, 0.0, 0.0, 0.0, 5e-5),  twist(0.9, 0.05, 0.01, 0.002, -0.004, 0.11),
          twist(-2.0, 3.0, 0.5, 0.3, -0.5, 0.9), twist(0.1, 0.2, 0.3, 0.0, 0.0, 3.1),
          twist(5.0, -1.0, 2.0, 1.2, 1.4, -1.3)};
}

TEST(Se3, ExpIsTheMatrixExponentialOfTheTwist) {
  for (const Vector6d& xi : twists()) {
    const Eigen::Matrix4d direct = twist_matrix(xi).exp();
    EXPECT_LT((se3_exp(xi).matrix() - direct).cwiseAbs().maxCoeff(), 1e-12) << xi.transpose();
  }
}

TEST(Se3, LogIsTheMatrixLogarithmOfTheMotion) {
  for (const Vector6d& xi : twists()) {
    const Eigen::Isometry3d T(Eigen::Matrix4d(twist_matrix(xi).exp()));
    const Eigen::Matrix4d direct = T.matrix().log();
    EXPECT_LT((twist_matrix(se3_log(T)) - direct).cwiseAbs().maxCoeff(), 1e-9) << xi.transpose();
    EXPECT_LT((se3_log(T) - xi).cwiseAbs().maxCoeff(), 1e-9) << xi.transpose();
  }
}

TEST(Se3, InterpolationIsTheConstantVelocityMotionAfterThatFraction) {
  for (const Vector6d& xi : twists()) {
    const Eigen::Isometry3d T = se3_exp(xi);
    EXPECT_TRUE(interpolate_motion(T, 0.0).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
    EXPECT_LT((interpolate_motion(T, 1.0).matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-9);
    // At a constant velocity the body is at exp(s·ξ) after the fraction s, and two halves make T.
    for (double s : {-0.5, 0.25, 0.5, 0.9, 1.5}) {
      const Eigen::Matrix4d direct = (s * twist_matrix(xi)).exp();
      EXPECT_LT((interpolate_motion(T, s).matrix() - direct).cwiseAbs().maxCoeff(), 1e-9) << s;
    }
    const Eigen::Isometry3d half = interpolate_motion(T, 0.5);
    EXPECT_LT(((half * half).matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(Se3, ACarOnACircleStaysOnItsArc) {
  // 10 m/s round a circle of 14 m radius turning left, for 0.1 s: the screw motion is the arc.
  const double radius = 14.0, speed = 10.0, seconds = 0.1, yaw_rate = speed / radius;
  const auto on_arc = [&](double t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    const double angle = yaw_rate * t;
    pose.translation() = Eigen::Vector3d(radius * std::sin(angle), radius * (1.0 - std::cos(angle)), 0.0);
    pose.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return pose;
  };
  const Eigen::Isometry3d step = on_arc(seconds);
  for (double t : {0.01, 0.037, 0.05, 0.09}) {
    const Eigen::Isometry3d between = interpolate_motion(step, t / seconds);
    EXPECT_LT((between.matrix() - on_arc(t).matrix()).cwiseAbs().maxCoeff(), 1e-12) << t;
  }
}

}  // namespace
}  // namespace sextant
