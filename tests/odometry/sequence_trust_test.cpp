// The sequence check of odometry (sequence_trust.hpp): a step far below its neighbours' overlap or
// far above their fit is suspect; before the history is long enough, or for an untrusted step,
// nothing changes; only trusted steps enter the window.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sextant/odometry/sequence_trust.hpp"
#include "sextant_test/trusted_quality.hpp"

namespace sextant {
namespace {

using test::trusted;

TEST(SequenceTrust, FlagsAStepOutOfItsSequencesRange) {
  SequenceTrust sequence;
  RegistrationQuality early = trusted(0.2, 3.0);
  sequence.check(early);  // no history yet: the absolute checks alone decide
  EXPECT_TRUE(early.trusted());
  for (const double overlap : {0.85, 0.9, 0.8, 0.88}) sequence.record(trusted(overlap, 1.0));
  RegistrationQuality untrusted = trusted(0.1, 1.0);
  untrusted.trust = Trust::kLowOverlap;
  sequence.record(untrusted);  // ignored: the median stays that of the trusted steps
  RegistrationQuality normal = trusted(0.80, 1.05);
  sequence.check(normal);
  EXPECT_TRUE(normal.trusted()) << normal.reason;
  RegistrationQuality slid = trusted(0.70, 1.0);  // below 0.9 × the median 0.88 (window of 4: upper median)
  sequence.check(slid);
  EXPECT_EQ(slid.trust, Trust::kSuspect);
  EXPECT_NE(slid.reason.find("70.0 %"), std::string::npos) << slid.reason;
  RegistrationQuality poor = trusted(0.9, 1.2);  // above 1.1 × the median fit 1.0
  sequence.check(poor);
  EXPECT_EQ(poor.trust, Trust::kSuspect);
  EXPECT_NE(poor.reason.find("fit 1.20"), std::string::npos) << poor.reason;
}

// Scans that fit better than the Gaussians predict (the synthetic campus: 0.8–0.9 × the prediction): a
// step fitting 1.0 is 1.18 × its neighbours' median but fits as a right pose does, within the check's
// 1.1 of the prediction, and stays trusted; one fitting 1.15 is above both and is suspect.
TEST(SequenceTrust, AFitAsGoodAsARightPosesIsNotSuspectForItsNeighbours) {
  SequenceTrust sequence;
  for (const double fit : {0.84, 0.85, 0.86, 0.85}) sequence.record(trusted(0.9, fit));
  RegistrationQuality predicted = trusted(0.9, 1.0);
  sequence.check(predicted);
  EXPECT_TRUE(predicted.trusted()) << predicted.reason;
  RegistrationQuality worse = trusted(0.9, 1.15);
  sequence.check(worse);
  EXPECT_EQ(worse.trust, Trust::kSuspect);
  EXPECT_NE(worse.reason.find("fit 1.15"), std::string::npos) << worse.reason;
}

TEST(SequenceTrust, WindowForgetsOldSteps) {
  SequenceTrustSettings settings;
  settings.window = 3;
  SequenceTrust sequence(settings);
  for (int i = 0; i < 3; ++i) sequence.record(trusted(0.9, 1.0));
  for (int i = 0; i < 3; ++i) sequence.record(trusted(0.5, 1.0));  // a sparser stretch
  RegistrationQuality q = trusted(0.5, 1.0);
  sequence.check(q);
  EXPECT_TRUE(q.trusted()) << q.reason;
}

// The fit bar in the sequence's units: its trusted steps' median fit, from the third on, raises the
// absolute bar of 1.3 by that factor where the right steps fit worse than predicted, and never lowers it.
TEST(SequenceTrust, TheFitBarFollowsTheFitOfTheTrustedSteps) {
  SequenceTrust sequence;
  EXPECT_FALSE(sequence.median_fit()) << "no history";
  sequence.record(trusted(0.9, 1.12));
  sequence.record(trusted(0.9, 1.08));
  EXPECT_FALSE(sequence.median_fit()) << "fewer than min_history";
  RegistrationQuality untrusted = trusted(0.9, 1.6);
  untrusted.trust = Trust::kSuspect;
  sequence.record(untrusted);  // ignored
  sequence.record(trusted(0.9, 1.10));
  ASSERT_TRUE(sequence.median_fit());
  EXPECT_DOUBLE_EQ(*sequence.median_fit(), 1.10);
  EXPECT_NEAR(fit_bar(1.3, sequence.median_fit()), 1.43, 1e-12);
  EXPECT_DOUBLE_EQ(fit_bar(1.3, std::nullopt), 1.3);
  EXPECT_DOUBLE_EQ(fit_bar(1.3, 0.85), 1.3) << "a scene that fits better than predicted keeps the bar";
  // With the bar, a right step of a sparse sensor (1.35) passes the absolute check and a slid one (1.6,
  // 1.45 × its neighbours) does not.
  QualitySettings quality;
  quality.max_fit_ratio = fit_bar(quality.max_fit_ratio, sequence.median_fit());
  RegistrationResult r;
  r.converged = true;
  r.why = Termination::kConverged;
  r.H = Matrix6d::Identity();
  r.input_points = 100;
  r.matched_points = 90;
  r.predicted_matched_score = 3.0;
  PointCloud input;
  input.push_back(Eigen::Vector3f(10.0f, 0.0f, 0.0f));
  r.mean_matched_score = 3.0 * 1.35;
  EXPECT_TRUE(assess_registration(r, input, quality).trusted());
  EXPECT_FALSE(assess_registration(r, input, QualitySettings{}).trusted()) << "above the plain 1.3";
  r.mean_matched_score = 3.0 * 1.6;
  EXPECT_EQ(assess_registration(r, input, quality).trust, Trust::kSuspect);
}

// No motion is what a lidar's rings always offer: without a trusted motion to confirm it, an answer
// within the ambiguity distance of no motion is believed only when it fits as two scans from one
// place do (fit ≤ 1.1 × the prediction). Moving answers, good fits and untrusted steps are left as they are.
TEST(SequenceTrust, NoMotionIsTrustedOnlyWithTheFitOfOnePlace) {
  const QualitySettings tolerance;  // 1 m, 5°
  const auto moved = [](double x, double yaw_deg) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = x;
    T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return T;
  };
  RegistrationQuality standing_poorly = trusted(0.83, 1.28);
  check_unconfirmed_no_motion(standing_poorly, moved(0.4, 1.0), tolerance);
  EXPECT_EQ(standing_poorly.trust, Trust::kSuspect);
  EXPECT_NE(standing_poorly.reason.find("fit 1.28"), std::string::npos) << standing_poorly.reason;
  RegistrationQuality standing_well = trusted(0.97, 1.04);
  check_unconfirmed_no_motion(standing_well, moved(0.4, 1.0), tolerance);
  EXPECT_TRUE(standing_well.trusted()) << standing_well.reason;
  RegistrationQuality driving = trusted(0.75, 1.28);  // 5.7 m: not the rings' answer
  check_unconfirmed_no_motion(driving, moved(5.7, 0.0), tolerance);
  EXPECT_TRUE(driving.trusted()) << driving.reason;
  RegistrationQuality turning = trusted(0.8, 1.28);  // 8° of yaw in place: far from no motion too
  check_unconfirmed_no_motion(turning, moved(0.0, 8.0), tolerance);
  EXPECT_TRUE(turning.trusted()) << turning.reason;
  RegistrationQuality low = trusted(0.3, 1.28);
  low.trust = Trust::kLowOverlap;
  low.reason = "30.0 % of the input matched";
  check_unconfirmed_no_motion(low, moved(0.1, 0.0), tolerance);
  EXPECT_EQ(low.trust, Trust::kLowOverlap);
  EXPECT_EQ(low.reason, "30.0 % of the input matched");
}

// A velocity measured over 0.8 s, a step of 1.4 s: their mid-times lie 1.1 s apart, so at 1 g the
// velocity changes by at most 10.8 m/s and the step's motion by 15.1 m.
TEST(SequenceTrust, ReachableDepartureFromTheConstantVelocityGuess) {
  EXPECT_NEAR(reachable_departure(0.8, 1.4, 9.81), 9.81 * 1.4 * 1.1, 1e-12);
  EXPECT_NEAR(reachable_departure(0.1, 0.1, 9.81), 0.0981, 1e-12) << "10 Hz scans: 10 cm";
  for (const double unknown : {reachable_departure(0.0, 1.0, 9.81), reachable_departure(1.0, -1.0, 9.81),
                               reachable_departure(1.0, NAN, 9.81), reachable_departure(1.0, 1.0, 0.0)})
    EXPECT_TRUE(std::isinf(unknown));
}

TEST(SequenceTrust, AMotionThePlatformCannotMakeIsNotTrusted) {
  const QualitySettings tolerance;  // 1 m
  const auto ahead = [](double x) { return Eigen::Isometry3d(Eigen::Translation3d(x, 0.0, 0.0)); };
  const Eigen::Isometry3d guess = ahead(-14.1);  // 10 m/s for 1.4 s
  const double reach = reachable_departure(0.8, 1.4, 9.81);
  const Eigen::Matrix3d straight = Eigen::Matrix3d::Identity();  // the last motion did not turn
  RegistrationQuality backwards = trusted(0.89, 1.26);           // MulRan as 32 rings, seed 5, 31 → 32
  check_reachable_motion(backwards, ahead(5.04), guess, straight, reach, tolerance);
  EXPECT_EQ(backwards.trust, Trust::kSuspect);
  EXPECT_NE(backwards.reason.find("19.1 m from the constant-velocity guess"), std::string::npos)
      << backwards.reason;
  EXPECT_NE(backwards.reason.find("beyond the 15.1 m"), std::string::npos) << backwards.reason;
  RegistrationQuality braking = trusted(0.9, 1.1);  // 8 m short of the guess: reachable
  check_reachable_motion(braking, ahead(-6.1), guess, straight, reach, tolerance);
  EXPECT_TRUE(braking.trusted()) << braking.reason;
  RegistrationQuality close = trusted(0.9, 1.1);  // beyond a 10 Hz step's reach, but within 1 m
  check_reachable_motion(close, ahead(0.5), ahead(0.0), straight, reachable_departure(0.1, 0.1, 9.81),
                         tolerance);
  EXPECT_TRUE(close.trusted()) << close.reason;
  RegistrationQuality no_clock = trusted(0.9, 1.1);
  check_reachable_motion(no_clock, ahead(5.04), guess, straight, reachable_departure(0.0, 1.4, 9.81),
                         tolerance);
  EXPECT_TRUE(no_clock.trusted()) << no_clock.reason;
  RegistrationQuality low = trusted(0.3, 1.1);
  low.trust = Trust::kLowOverlap;
  low.reason = "30.0 % of the input matched";
  check_reachable_motion(low, ahead(5.04), guess, straight, reach, tolerance);
  EXPECT_EQ(low.reason, "30.0 % of the input matched");
}

// A lidar turned ±15° about the vertical from scan to scan while its car drives straight on at 10 m/s,
// 0.5 s apart (MulRan 0–107 so turned, bench/sensor_variants.py): each step's 5 m lie ±15° off the
// sensor's x axis in turn, so the guess (the last step's motion in the sensor's frame) is 30° off, 2.6
// m away, beyond the 2.45 m 1 g allows in 0.5 s; yet the velocity did not change in the world at all.
// The last motion turned the sensor by 30°, and the guess's translation turned back by it is the step.
TEST(SequenceTrust, AVelocityHeldInTheWorldWhileTheSensorTurnsIsReachable) {
  const QualitySettings tolerance;  // 1 m
  const auto yaw = [](double degrees) {
    return Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ());
  };
  const auto moved = [&](double heading_deg, double sensor_yaw_deg) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = yaw(heading_deg) * Eigen::Vector3d(5.0, 0.0, 0.0);
    T.linear() = yaw(sensor_yaw_deg).toRotationMatrix();
    return T;
  };
  const double reach = reachable_departure(0.5, 0.5, 9.81);
  const Eigen::Isometry3d last = moved(15.0, 30.0);    // from the scan turned −15° to the one turned +15°
  const Eigen::Isometry3d guess = last;                // the same Δt: velocity × Δt is the last motion
  const Eigen::Isometry3d step = moved(-15.0, -30.0);  // and back: the car drives on along the same line
  ASSERT_GT((step.translation() - guess.translation()).norm(), reach);
  RegistrationQuality swinging = trusted(0.95, 1.05);
  check_reachable_motion(swinging, step, guess, last.linear(), reach, tolerance);
  EXPECT_TRUE(swinging.trusted()) << swinging.reason;
  // A motion near neither prediction still is out of reach: 5 m sideways to both.
  RegistrationQuality sideways = trusted(0.95, 1.05);
  check_reachable_motion(sideways, moved(-90.0, -30.0), guess, last.linear(), reach, tolerance);
  EXPECT_EQ(sideways.trust, Trust::kSuspect);
  // And without the turn of the last motion, the same step is out of reach of the guess alone.
  RegistrationQuality unturned = trusted(0.95, 1.05);
  check_reachable_motion(unturned, step, guess, Eigen::Matrix3d::Identity(), reach, tolerance);
  EXPECT_EQ(unturned.trust, Trust::kSuspect);
}

}  // namespace
}  // namespace sextant
