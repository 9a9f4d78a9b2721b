#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/rng.hpp"
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

TEST(ScanMatchingKf3d, RelativeFusionIsTheBestLinearFusionOfTheTwoIncrements) {
  ScanMatchingKfSettings s;
  s.odometry_sigma_translation = 0.2;  // Q = 0.04 on translations
  s.measurement = KfMeasurement::relative;
  const Matrix6d P0 = Matrix6d::Identity() * 0.01;
  ScanMatchingKf3d kf(s, Pose6{0.5, 0, 0, 0, 0, 0}, P0);
  Vector6d u = Vector6d::Zero();
  u[0] = 1.0;                                         // the odometer's increment
  const Pose6 z{0.5 + 1.1, 0.0, 0.0, 0.0, 0.0, 0.0};  // x̂ ⊕ T with T = 1.1
  const Matrix6d H = Matrix6d::Identity() * 20.0;     // R = 0.05
  const ScanMatchingKfStep step = kf.step(u, z, H);
  ASSERT_FALSE(step.alarm) << step.reason;
  const double q = 0.04, r = 0.05;
  EXPECT_NEAR(step.pose.x, 0.5 + (r * 1.0 + q * 1.1) / (q + r), 1e-12);  // (R u + Q T) / (Q + R)
  EXPECT_NEAR(step.P(0, 0), 0.01 + q * r / (q + r), 1e-12);              // P(k) + (Q⁻¹ + R⁻¹)⁻¹
}

/// The mean over `runs` simulated sequences of the final pose's NEES eᵀP⁻¹e (6 dof) when an odometer
/// (error ~ Q) and a matcher (error ~ R = H⁻¹) each measure every increment of a random walk, the
/// matcher's pose given as x̂(k|k) ⊕ T, as the sequence kind gives it.
double mean_final_nees(KfMeasurement measurement, int runs, int steps) {
  ScanMatchingKfSettings s;
  s.odometry_sigma_translation = 0.3;
  s.odometry_sigma_rotation = 0.02;
  s.alarm_translation = s.alarm_rotation = 1e9;  // no alarms: the fusion alone
  s.measurement = measurement;
  const Vector6d q = s.process_noise().diagonal();
  const Vector6d r = (Vector6d() << 0.01, 0.02, 0.005, 1e-4, 2e-4, 5e-5).finished();  // R, diagonal
  const Matrix6d H = r.cwiseInverse().asDiagonal();
  Rng rng(7);
  double total = 0;
  for (int run = 0; run < runs; ++run) {
    ScanMatchingKf3d kf(s, Pose6{}, Matrix6d::Identity() * 1e-6);
    Vector6d truth = Vector6d::Zero();
    for (int k = 0; k < steps; ++k) {
      Vector6d d, u, t;
      for (int i = 0; i < 6; ++i) {
        d[i] = rng.normal(0.0, i < 3 ? 1.0 : 0.01);
        u[i] = d[i] + rng.normal(0.0, std::sqrt(q[i]));
        t[i] = d[i] + rng.normal(0.0, std::sqrt(r[i]));
      }
      truth += d;
      kf.step(u, Pose6::from_vector(kf.pose().vector() + t), H);
    }
    const Vector6d e = kf.pose().vector() - truth;
    total += e.dot(kf.covariance().llt().solve(e));
  }
  return total / runs;
}

TEST(ScanMatchingKf3d, RelativeFusionIsConsistentWhereTable33IsNot) {
  // A consistent filter's mean NEES over M runs lies in χ²_{6M}'s central 99 % over M.
  constexpr int kRuns = 200, kSteps = 40;
  const double lo = chi_square_quantile(0.005, 6.0 * kRuns) / kRuns;
  const double hi = chi_square_quantile(0.995, 6.0 * kRuns) / kRuns;
  const double relative = mean_final_nees(KfMeasurement::relative, kRuns, kSteps);
  EXPECT_GT(relative, lo);
  EXPECT_LT(relative, hi);
  // Table 3.3 takes x̂ ⊕ T as a pose measured on its own: P stays below R while the error adds up.
  EXPECT_GT(mean_final_nees(KfMeasurement::absolute, kRuns, kSteps), 5 * hi);
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
