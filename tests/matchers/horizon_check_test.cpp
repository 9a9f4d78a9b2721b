// An answer without translation, confirmed by the points above the horizon (horizon_check.hpp): the
// rules on scripted registrations of those points (each a pose and its assessment).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "sextant/core/units.hpp"
#include "sextant/matchers/horizon_check.hpp"
#include "sextant_test/trusted_quality.hpp"

namespace sextant {
namespace {

using test::trusted;

TEST(HorizonCheck, AboveTheHorizonIsWhatLooksUp) {
  PointCloud scan;
  for (const float z : {-1.5f, 0.0f, 0.3f, -0.2f, 2.0f}) scan.push_back({10.0f, 1.0f, z});
  const PointCloud above = above_horizon(scan);
  ASSERT_EQ(above.size(), 2u);
  EXPECT_EQ(above.points()[0].z(), 0.3f);
  EXPECT_EQ(above.points()[1].z(), 2.0f);
}

/// A pose `x` metres ahead, turned `yaw_deg` about the vertical.
Eigen::Isometry3d pose(double x, double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  T.linear() = Eigen::AngleAxisd(yaw_deg * kRadPerDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

RegistrationQuality with_trust(RegistrationQuality q, Trust trust) {
  q.trust = trust;
  return q;
}

/// The points above the horizon registered alone from an answer to `local` (with `local_quality`), and
/// searched for with the wide basin to `wide` when `wide_quality` is given.
AboveHorizon said(const Eigen::Isometry3d& local, const RegistrationQuality& local_quality,
                  const Eigen::Isometry3d& wide = Eigen::Isometry3d::Identity(),
                  std::optional<RegistrationQuality> wide_quality = std::nullopt) {
  AboveHorizon a;
  a.local = local;
  a.local_quality = local_quality;
  a.wide = wide;
  a.wide_quality = wide_quality;
  return a;
}

/// The trust of a trusted answer at `answer` (overlap 0.95, fit 1.08) once the points above the horizon
/// said `above`, and its reason.
RegistrationQuality judged(const Eigen::Isometry3d& answer, const AboveHorizon& above) {
  RegistrationQuality q = trusted(0.95, 1.08);
  check_no_motion_above_horizon(q, answer, above, QualitySettings{});
  return q;
}

// MulRan 0–107 as 16 rings (seed 2, keyframes 57 → 58): the answer 0.11 m fits 1.08 × the prediction,
// as a stop fits; the points above the horizon alone move 1.89 m from it, trusted.
// No translation means within the 1 m tolerance, turned any way: the rings are circles about the sensor.
TEST(HorizonCheck, AnAnswerWithoutTranslationMayTurn) {
  const QualitySettings tolerance;
  EXPECT_TRUE(answer_without_translation(pose(0.99, 0.0), tolerance));
  EXPECT_TRUE(answer_without_translation(pose(0.1, 30.0), tolerance));
  EXPECT_FALSE(answer_without_translation(pose(1.01, 0.0), tolerance));
}

TEST(HorizonCheck, NoTranslationIsNotTrustedWhereThePointsAboveTheHorizonLeaveIt) {
  const RegistrationQuality moved = judged(pose(0.11, 0.8), said(pose(2.0, 1.6), trusted(0.99, 1.11)));
  EXPECT_EQ(moved.trust, Trust::kSuspect);
  EXPECT_NE(moved.reason.find("registered alone from it, move 1.89 m and 0.8°"), std::string::npos)
      << moved.reason;
  // Every 4th ring counted from another (seed 3, keyframes 2 → 3): they leave 2.9 m towards the truth
  // and fit 1.32 there, a poor fit, but the answer is not where they rest.
  const auto poorly = with_trust(trusted(0.62, 1.32), Trust::kSuspect);
  EXPECT_EQ(judged(pose(0.04, 0.0), said(pose(2.9, 0.0), poorly)).trust, Trust::kSuspect);
  // Keyframes 65 → 66: an answer turned 7.1° in place, where they match 44 %.
  const RegistrationQuality turned =
      judged(pose(0.09, 7.1), said(pose(1.6, 9.6), with_trust(trusted(0.44, 1.40), Trust::kLowOverlap)));
  EXPECT_EQ(turned.trust, Trust::kSuspect);
  EXPECT_NE(turned.reason.find("only 44.0 % of the points above the horizon match"), std::string::npos)
      << turned.reason;
}

// Where their registration from the answer stays, fitting poorly (1.77), the wide basin's search decides:
// 3.1 m away, trusted, or fitting clearly better (1.32 < 1.77 / 1.1), the answer is suspect; fitting about
// as well (1.65) it stands, and so does one where neither tells anything (degenerate).
TEST(HorizonCheck, NoTranslationIsNotTrustedWhereTheSearchAboveTheHorizonFitsClearlyBetter) {
  const Eigen::Isometry3d answer = pose(0.05, 0.0), there = pose(3.15, 0.0), near = pose(0.28, 0.0);
  const auto stays = with_trust(trusted(0.61, 1.77), Trust::kSuspect);
  EXPECT_FALSE(said(near, stays).telling(answer, QualitySettings{}));
  EXPECT_EQ(judged(answer, said(near, stays, there, trusted(0.78, 1.25))).trust, Trust::kSuspect);
  const RegistrationQuality better =
      judged(answer, said(near, stays, there, with_trust(trusted(0.78, 1.32), Trust::kSuspect)));
  EXPECT_EQ(better.trust, Trust::kSuspect);
  EXPECT_NE(better.reason.find("fit 1.32 × the prediction 3.10 m and 0.0° away and 1.77 at it"),
            std::string::npos)
      << better.reason;
  EXPECT_TRUE(
      judged(answer, said(near, stays, there, with_trust(trusted(0.78, 1.65), Trust::kSuspect))).trusted());
  const auto blind = with_trust(trusted(0.9, 1.0), Trust::kDegenerate);
  EXPECT_TRUE(judged(answer, said(there, blind, there, blind)).trusted());
}

// At a stop the points above the horizon stay (5 cm) and fit: the answer stands, and no search is needed.
// An answer that moves (2.4 m), one where no point lies above the horizon, and one already untrusted are
// left alone.
TEST(HorizonCheck, AStopIsConfirmedByThePointsAboveTheHorizon) {
  const AboveHorizon stop = said(pose(0.10, 0.1), trusted(0.93, 1.01));
  EXPECT_TRUE(stop.telling(pose(0.05, 0.0), QualitySettings{}));
  EXPECT_TRUE(judged(pose(0.05, 0.0), stop).trusted());
  EXPECT_TRUE(judged(pose(2.4, 0.0), said(pose(4.0, 0.0), trusted(0.9, 1.0))).trusted());
  EXPECT_TRUE(judged(pose(0.05, 0.0), AboveHorizon{}).trusted())
      << "no point above the horizon: nothing said";
  RegistrationQuality low = with_trust(trusted(0.3, 1.0), Trust::kLowOverlap);
  low.reason = "30.0 % of the input matched";
  check_no_motion_above_horizon(low, pose(0.1, 0.0), said(pose(3.0, 0.0), trusted(0.9, 1.0)),
                                QualitySettings{});
  EXPECT_EQ(low.reason, "30.0 % of the input matched");
}

}  // namespace
}  // namespace sextant
