// Odometry on a solid-state lidar carried on foot (issue 62): 30 keyframes of the shared Livox Avia
// walk round HKU's main building (../shared/data/livox_avia_hkumb; about 70° × 77° of view, a
// non-repetitive pattern, 3–5k points per keyframe, a person walking 0.2 m and turning up to 6° per
// keyframe; its reference is FAST-LIO2's lidar-inertial odometry, good step by step). The checks that
// rest on a spinning lidar's rings and a car's metres do not apply: measured, not declared.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "sextant/core/dataset.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/sensor_kind.hpp"
#include "sextant/odometry/odometry.hpp"
#include "shared_mulran.hpp"

namespace sextant {
namespace {

const std::filesystem::path kAvia = std::filesystem::path(SEXTANT_SHARED_DATA_DIR) / "livox_avia_hkumb";

/// Keyframes 295–324: the walk turns a corner, up to 6.5° per keyframe.
constexpr std::size_t kFirst = 295, kCount = 30;

OdometryResult walk(const Dataset& dataset, SensorKind sensor, Platform platform) {
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // what `sextant odometry` takes for a folder without odometry
  s.sensor = sensor;
  s.platform = platform;
  return run_odometry(dataset, s, kFirst, kCount);
}

/// The steps of `r` that say trusted and lie more than 0.3 m or 3° from the reference's motion (the bar
/// of a sequence carried on foot).
std::size_t trusted_steps_off(const Dataset& dataset, const OdometryResult& r) {
  std::size_t off = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const Eigen::Isometry3d truth =
        relative(*dataset.ground_truth(kFirst + i), *dataset.ground_truth(kFirst + i + 1));
    const Eigen::Isometry3d e = relative(truth, r.steps[i].relative);
    const bool wrong = translation_norm(e) > 0.3 || rotation_angle(e) * kDegPerRad > 3.0;
    if (r.steps[i].trusted() && wrong) {
      ++off;
      ADD_FAILURE() << "step " << kFirst + i << " is " << translation_norm(e) << " m and "
                    << rotation_angle(e) * kDegPerRad << "° off and says trusted";
    }
  }
  return off;
}

TEST(SolidStateWalk, TheSensorIsMeasuredFromItsFirstScan) {
  if (!std::filesystem::is_directory(kAvia)) GTEST_SKIP() << "no " << kAvia;
  const auto avia = open_dataset(kAvia);
  const SensorDetection d = detect_sensor(avia->scan(0));
  EXPECT_EQ(d.kind, SensorKind::solid_state);
  EXPECT_LT(d.azimuth_coverage, 0.3) << "a 70° field of view is a fifth of the circle";
  if (!std::filesystem::is_directory(test::kMulran)) GTEST_SKIP() << "no " << test::kMulran;
  const SensorDetection ouster = detect_sensor(open_dataset(test::kMulran)->scan(0));
  EXPECT_EQ(ouster.kind, SensorKind::spinning);
  EXPECT_GT(ouster.azimuth_coverage, 0.7);
}

TEST(SolidStateWalk, IsRightOrSaysSoWithTheDefaults) {
  if (!std::filesystem::is_directory(kAvia)) GTEST_SKIP() << "no " << kAvia;
  const auto avia = open_dataset(kAvia);
  const OdometryResult r = walk(*avia, SensorKind::automatic, Platform::automatic);
  ASSERT_EQ(r.steps.size(), kCount - 1);
  EXPECT_EQ(r.sensor.kind, SensorKind::solid_state);
  ASSERT_TRUE(r.typical_step.has_value());
  EXPECT_LT(*r.typical_step, 0.6) << "a person walks tenths of a metre per keyframe";
  EXPECT_DOUBLE_EQ(r.tolerance.ambiguity_metres, kHandheldToleranceMetres);
  EXPECT_EQ(trusted_steps_off(*avia, r), 0u);
  // Measured: the first step, against a map of one scan (58 % overlap, fit 1.36), and a turn of 6° that
  // shows a new view (75 % overlap where the steps before matched 89 %), both right within 5 cm.
  EXPECT_LE(r.untrusted(), 2u) << "right steps of a walk are believed";
  // The end against the reference: a walk of about 7 m.
  const Eigen::Isometry3d end = relative(r.poses.front(), r.poses.back());
  const Eigen::Isometry3d truth =
      relative(*avia->ground_truth(kFirst), *avia->ground_truth(kFirst + kCount - 1));
  EXPECT_GT(translation_norm(truth), 4.0);
  EXPECT_LT(translation_norm(relative(truth, end)), 0.2);
  EXPECT_LT(rotation_angle(relative(truth, end)) * kDegPerRad, 2.0);
}

// The same steps judged as a spinning lidar on a car: "no motion" is anything within 1 m, and a
// lidar's rings are supposed to coincide there, so the walker's right steps are doubted.
TEST(SolidStateWalk, ACarsSpinningLidarChecksDoubtTheWalkersRightSteps) {
  if (!std::filesystem::is_directory(kAvia)) GTEST_SKIP() << "no " << kAvia;
  const auto avia = open_dataset(kAvia);
  const OdometryResult as_car = walk(*avia, SensorKind::spinning, Platform::car);
  EXPECT_EQ(as_car.sensor.kind, SensorKind::spinning) << "declared wins over measured";
  EXPECT_DOUBLE_EQ(as_car.tolerance.ambiguity_metres, 1.0);
  EXPECT_GE(as_car.untrusted(), 5u);
}

}  // namespace
}  // namespace sextant
