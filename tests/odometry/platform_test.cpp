// The size of a wrong step for each platform (platform.hpp), and the typical step it follows.
#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/odometry/platform.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d step_of(double metres) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(metres * 0.6, metres * 0.8, 0.0);
  return T;
}

TEST(Platform, ACarKeepsItsMetresWhateverItsSteps) {
  const QualitySettings car = platform_tolerance({}, Platform::car, 0.05);
  EXPECT_DOUBLE_EQ(car.ambiguity_metres, 1.0);
  EXPECT_DOUBLE_EQ(car.ambiguity_degrees, 5.0);
}

TEST(Platform, HandheldIsTheBarOfAWalk) {
  const QualitySettings walk = platform_tolerance({}, Platform::handheld, 6.0);
  EXPECT_DOUBLE_EQ(walk.ambiguity_metres, 0.3);
  EXPECT_DOUBLE_EQ(walk.ambiguity_degrees, 3.0);
  QualitySettings tight;
  tight.ambiguity_metres = 0.1;
  tight.ambiguity_degrees = 1.0;
  const QualitySettings tighter = platform_tolerance(tight, Platform::handheld, std::nullopt);
  EXPECT_DOUBLE_EQ(tighter.ambiguity_metres, 0.1) << "never looser than the settings";
  EXPECT_DOUBLE_EQ(tighter.ambiguity_degrees, 1.0);
}

TEST(Platform, AutoFollowsTheTypicalStepBetweenTheBars) {
  EXPECT_DOUBLE_EQ(platform_tolerance({}, Platform::automatic, std::nullopt).ambiguity_metres, 1.0)
      << "a car's until the steps are known";
  EXPECT_DOUBLE_EQ(platform_tolerance({}, Platform::automatic, 5.2).ambiguity_metres, 1.0);
  EXPECT_DOUBLE_EQ(platform_tolerance({}, Platform::automatic, 1.9).ambiguity_metres, 0.95) << "half a step";
  EXPECT_DOUBLE_EQ(platform_tolerance({}, Platform::automatic, 0.5).ambiguity_metres, 0.3);
  const QualitySettings middle = platform_tolerance({}, Platform::automatic, 1.3);
  EXPECT_DOUBLE_EQ(middle.ambiguity_metres, 0.65);
  EXPECT_NEAR(middle.ambiguity_degrees, 4.0, 1e-12) << "halfway between 3° and 5°";
  // Everything else stays.
  QualitySettings base;
  base.max_fit_ratio = 1.7;
  EXPECT_DOUBLE_EQ(platform_tolerance(base, Platform::automatic, 0.2).max_fit_ratio, 1.7);
}

TEST(Platform, TheTypicalStepIsTheMedianOfTheLastTrustedSteps) {
  MotionScale scale(5, 3);
  scale.record(step_of(0.2));
  scale.record(step_of(0.25));
  EXPECT_FALSE(scale.typical_step()) << "too few steps";
  scale.record(step_of(9.0));  // one jump does not move a median
  ASSERT_TRUE(scale.typical_step());
  EXPECT_NEAR(*scale.typical_step(), 0.25, 1e-12);
  for (int k = 0; k < 5; ++k) scale.record(step_of(4.0));  // the window forgets
  EXPECT_NEAR(*scale.typical_step(), 4.0, 1e-12);
}

TEST(Platform, NamesRoundTripAndAnUnknownOneIsNamed) {
  for (const Platform p : {Platform::automatic, Platform::car, Platform::handheld})
    EXPECT_EQ(parse_enum(kPlatformNames, to_string(p), "platform"), p);
  EXPECT_THROW(parse_enum(kPlatformNames, "drone", "--platform"), InputError);
}

}  // namespace
}  // namespace sextant
