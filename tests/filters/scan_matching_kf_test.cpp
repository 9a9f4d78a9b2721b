#include <gtest/gtest.h>

#include <cmath>

#include "sextant/filters/scan_matching_kf.hpp"
#include "sextant_test/finite_differences.hpp"

namespace sextant {
namespace {

TEST(ScanMatchingKf3d, MatchesTheScalarKalmanFilterOfTable33) {
  ScanMatchingKfSettings s;
  s.odometry_sigma_translation = 0.2;  // Q = 0.04 on translations
  const Matrix6d P0 = Matrix6d::Identity() * 0.01;
  ScanMatchingKf3d kf(s, Pose6{}, P0);
  Vector6d u = Vector6d::Zero();
  u[0] = 1.0;
  const Pose6 z{1.1, 0.0, 0.0, 0.0, 0.0, 0.0};
  const Matrix6d H = Matrix6d::Identity() * 20.0;  // R = 0.05
  const ScanMatchingKfStep step = kf.step(u, z, H);
  ASSERT_FALSE(step.alarm) << step.reason;
  const double p = 0.01 + 0.04, gain = p / (p + 0.05);
  EXPECT_NEAR(step.pose.x, 1.0 + gain * 0.1, 1e-12);
  EXPECT_NEAR(step.P(0, 0), (1 - gain) * p, 1e-12);
}

TEST(ScanMatchingKf3d, AlarmKeepsOdometry) {
  ScanMatchingKf3d kf({}, Pose6{}, Matrix6d::Identity() * 0.01);
  Vector6d u = Vector6d::Zero();
  u[0] = 1.0;
  const ScanMatchingKfStep far = kf.step(u, Pose6{3.0, 0, 0, 0, 0, 0}, Matrix6d::Identity() * 20.0);
  EXPECT_TRUE(far.alarm);
  EXPECT_DOUBLE_EQ(far.pose.x, 1.0);
  const ScanMatchingKfStep bad_h = kf.step(u, Pose6{2.0, 0, 0, 0, 0, 0}, -Matrix6d::Identity());
  EXPECT_TRUE(bad_h.alarm);
  EXPECT_DOUBLE_EQ(bad_h.pose.x, 2.0);
  const ScanMatchingKfStep turned = kf.step(u, Pose6{3.0, 0, 0, 0, 0, 0.5}, Matrix6d::Identity() * 20.0);
  EXPECT_TRUE(turned.alarm);
  EXPECT_NE(turned.reason.find("rotation"), std::string::npos);
}

TEST(AckermannScanMatchingEkf, JacobianAndExactMeasurement) {
  const Eigen::Vector3d from(1.0, 2.0, 0.7), to(2.0, 2.5, 0.9);
  const Eigen::Matrix3d H = AckermannScanMatchingEkf::relative_jacobian(from);
  // Each entry within 1e-8/√3 absolute: every column within 1e-8 in norm, as before.
  test::expect_jacobian_near(
      H,
      test::central_jacobian(
          [&](const Eigen::VectorXd& x) {
            return Eigen::VectorXd(AckermannScanMatchingEkf::relative_measurement(from, x));
          },
          to),
      1e-8 / std::sqrt(3.0), "H", test::Bound::absolute);
  // A near-perfect measurement (tiny R) pulls the estimate onto the measured relative pose.
  AckermannScanMatchingEkf ekf({}, from, Eigen::Matrix3d::Identity() * 1e-6);
  ekf.predict(Eigen::Vector2d(2.0, 0.1), Eigen::Vector2d(0.25, 1e-3).asDiagonal());
  const Eigen::Vector3d xi = AckermannScanMatchingEkf::relative_measurement(from, to);
  ASSERT_TRUE(ekf.update(xi, Eigen::Matrix3d::Identity() * 1e-10));
  EXPECT_LT((ekf.pose() - to).norm(), 1e-3);
}

}  // namespace
}  // namespace sextant
