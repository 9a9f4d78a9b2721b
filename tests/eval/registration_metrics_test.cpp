#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/core/units.hpp"
#include "sextant/eval/registration_metrics.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d pose(double x, double y, double z, double a, double b, double g) {
  return to_isometry(Pose6{x, y, z, a, b, g});
}

TEST(RegistrationError, PerParameterInCentimetresAndDegrees) {
  const Eigen::Isometry3d gt = pose(3.0, -1.0, 0.5, 0.1, -0.2, 1.3);
  const Eigen::Isometry3d est = gt * pose(0.10, -0.20, 0.05, 0.01, 0.02, -0.03);
  const RegistrationError e = registration_error(est, gt);
  ASSERT_TRUE(e.finite);
  const double expected[6] = {10.0, -20.0, 5.0, 0.01 * kDegPerRad, 0.02 * kDegPerRad, -0.03 * kDegPerRad};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(e.parameters[k], expected[k], 1e-9) << parameter_names()[k];
  EXPECT_NEAR(e.translation_cm, std::sqrt(100.0 + 400.0 + 25.0), 1e-9);
  EXPECT_NEAR(e.rotation_deg, rotation_angle(pose(0, 0, 0, 0.01, 0.02, -0.03)) * kDegPerRad, 1e-9);
}

TEST(RegistrationError, UosAxes) {
  // x_uos = −y, y_uos = z, z_uos = x.
  const RegistrationError t =
      registration_error(pose(0.1, 0.2, 0.3, 0, 0, 0), Eigen::Isometry3d::Identity(), AxisConvention::uos);
  EXPECT_NEAR(t.parameters[0], -20.0, 1e-9);
  EXPECT_NEAR(t.parameters[1], 30.0, 1e-9);
  EXPECT_NEAR(t.parameters[2], 10.0, 1e-9);
  // A yaw about our z is the heading β_uos about y_uos; the reflection flips its sign.
  const RegistrationError yaw =
      registration_error(pose(0, 0, 0, 0, 0, 0.1), Eigen::Isometry3d::Identity(), AxisConvention::uos);
  EXPECT_NEAR(yaw.parameters[3], 0.0, 1e-9);
  EXPECT_NEAR(yaw.parameters[4], -0.1 * kDegPerRad, 1e-9);
  EXPECT_NEAR(yaw.parameters[5], 0.0, 1e-9);
  // Roll about our x is about z_uos.
  const RegistrationError roll =
      registration_error(pose(0, 0, 0, 0.1, 0, 0), Eigen::Isometry3d::Identity(), AxisConvention::uos);
  EXPECT_NEAR(roll.parameters[5], -0.1 * kDegPerRad, 1e-9);
  EXPECT_NEAR(roll.rotation_deg, 0.1 * kDegPerRad, 1e-9);
}

TEST(RegistrationError, NonFiniteEstimateIsFailureNotCrash) {
  Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
  bad.translation().x() = std::numeric_limits<double>::quiet_NaN();
  const RegistrationError e = registration_error(bad, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(e.finite);
  EXPECT_FALSE(SuccessCriterion{}.succeeded(e, true));
}

TEST(SuccessCriterion, ThesisThresholds) {
  const SuccessCriterion c50 = thesis_success_criterion("translation_50cm");
  const SuccessCriterion c200 = thesis_success_criterion("translation_200cm_rotation_10deg");
  RegistrationError e;
  e.translation_cm = 49.9;
  e.rotation_deg = 12.0;
  EXPECT_TRUE(c50.succeeded(e, true));
  EXPECT_FALSE(c200.succeeded(e, true));
  e.translation_cm = 150.0;
  e.rotation_deg = 9.0;
  EXPECT_FALSE(c50.succeeded(e, true));
  EXPECT_TRUE(c200.succeeded(e, true));
  SuccessCriterion strict = c200;
  strict.require_converged = true;
  EXPECT_FALSE(strict.succeeded(e, false));
  EXPECT_THROW(thesis_success_criterion("bogus"), std::invalid_argument);
  std::string why;
  SuccessCriterion bad;
  bad.max_translation_cm = -1.0;
  EXPECT_FALSE(bad.valid(&why));
  EXPECT_FALSE(why.empty());
}

TEST(RegistrationStats, HandComputedTable) {
  std::vector<RegistrationSample> samples;
  const double tx_cm[4] = {10.0, 20.0, 30.0, 100.0};
  for (int k = 0; k < 4; ++k) {
    RegistrationSample s;
    s.ground_truth = pose(1.0 * k, 0, 0, 0, 0, 0.5 * k);
    s.estimate = s.ground_truth * pose(tx_cm[k] / 100.0, 0, 0, 0, 0, 0);
    s.iterations = 10 + k;
    s.seconds = 0.5 * (k + 1);
    s.matched_points = k < 2 ? 50 * (k + 1) : 0;
    s.total_points = k < 2 ? 200 : 0;
    samples.push_back(s);
  }
  RegistrationStats all = registration_stats(samples);
  EXPECT_EQ(all.count, 4u);
  EXPECT_EQ(all.successes, 3u);
  EXPECT_DOUBLE_EQ(all.success_rate, 0.75);
  EXPECT_NEAR(all.parameters[0].mean, 40.0, 1e-9);
  EXPECT_NEAR(all.parameters[0].max, 100.0, 1e-9);
  EXPECT_NEAR(all.parameters[0].std, std::sqrt((900.0 + 400.0 + 100.0 + 3600.0) / 3.0), 1e-9);
  EXPECT_NEAR(all.translation_cm.mean, 40.0, 1e-9);
  EXPECT_NEAR(all.iterations.mean, 11.5, 1e-12);
  EXPECT_NEAR(all.seconds.max, 2.0, 1e-12);
  EXPECT_EQ(all.matched_percent.count, 2u);
  EXPECT_NEAR(all.matched_percent.mean, 37.5, 1e-12);
  EXPECT_FALSE(all.success[3]);

  RegistrationStatsSettings only_successes;
  only_successes.errors_of_successes_only = true;
  const RegistrationStats ok = registration_stats(samples, only_successes);
  EXPECT_NEAR(ok.parameters[0].mean, 20.0, 1e-9);
  EXPECT_EQ(ok.iterations.count, 4u);

  const RegistrationStats none = registration_stats({});
  EXPECT_EQ(none.count, 0u);
  EXPECT_DOUBLE_EQ(none.success_rate, 0.0);
}

}  // namespace
}  // namespace sextant
