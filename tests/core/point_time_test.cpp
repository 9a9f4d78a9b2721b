// The per-point time field of drivers' records and its conversion to seconds from the scan's stamp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "sextant/core/io/point_time.hpp"

namespace sextant {
namespace {

TEST(PointTime, FindsEachDriversFieldAndPrefersTheFirstName) {
  EXPECT_EQ(find_point_time_field({"x", "y", "z", "intensity", "t", "ring"}), 4u);          // Ouster
  EXPECT_EQ(find_point_time_field({"x", "y", "z", "intensity", "ring", "time"}), 5u);       // Velodyne
  EXPECT_EQ(find_point_time_field({"x", "y", "z", "intensity", "timestamp", "ring"}), 4u);  // Hesai
  EXPECT_EQ(find_point_time_field({"x", "y", "z", "offset_time"}), 3u);                     // Livox
  EXPECT_EQ(find_point_time_field({"timestamp", "x", "y", "z", "t"}), 4u);
  EXPECT_FALSE(find_point_time_field({"x", "y", "z", "intensity", "ring", "times"}));
}

TEST(PointTime, IntegerFieldsAreNanosecondsFloatingOnesSeconds) {
  PointTimeConversion how;
  const std::vector<float> ouster = point_times_to_seconds({0, 50'000'000, 99'951'172}, true, 1.7e9, &how);
  EXPECT_FALSE(how.absolute);
  EXPECT_DOUBLE_EQ(how.seconds_per_unit, 1e-9);
  EXPECT_FLOAT_EQ(ouster[1], 0.05f);
  EXPECT_FLOAT_EQ(ouster[2], 0.099951172f);

  const std::vector<float> velodyne = point_times_to_seconds({-0.1, -0.05, 0.0}, false, std::nullopt, &how);
  EXPECT_FALSE(how.absolute);
  EXPECT_DOUBLE_EQ(how.seconds_per_unit, 1.0);
  EXPECT_FLOAT_EQ(velodyne[0], -0.1f);
}

TEST(PointTime, TimesSinceTheEpochBecomeRelativeToTheStampOrTheEarliestPoint) {
  PointTimeConversion how;
  const double stamp = 1565943695.2;
  const std::vector<float> hesai = point_times_to_seconds({stamp + 0.01, stamp + 0.09}, false, stamp, &how);
  EXPECT_TRUE(how.absolute);
  EXPECT_NEAR(hesai[0], 0.01f, 1e-6);
  EXPECT_NEAR(hesai[1], 0.09f, 1e-6);
  const std::vector<float> no_stamp =
      point_times_to_seconds({stamp + 0.03, stamp + 0.01}, false, std::nullopt);
  EXPECT_NEAR(no_stamp[0], 0.02f, 1e-6);
  EXPECT_NEAR(no_stamp[1], 0.0f, 1e-6);
  // livox_ros_driver2: float64 nanoseconds since the epoch.
  const std::vector<float> livox = point_times_to_seconds({stamp * 1e9 + 2e6}, false, stamp, &how);
  EXPECT_TRUE(how.absolute);
  EXPECT_DOUBLE_EQ(how.seconds_per_unit, 1e-9);
  EXPECT_NEAR(livox[0], 0.002f, 1e-6);
}

TEST(PointTime, NonFiniteValuesStayNonFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<float> s = point_times_to_seconds({1565943695.0, nan}, false, std::nullopt);
  EXPECT_FLOAT_EQ(s[0], 0.0f);
  EXPECT_TRUE(std::isnan(s[1]));
}

}  // namespace
}  // namespace sextant
