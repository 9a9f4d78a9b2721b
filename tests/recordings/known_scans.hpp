#pragma once
// Scans with known content for the recordings tests: scan k of a topic has `points` points, point j at
// (k + 0.5 j, −j, 0.25 k) m with intensity j and time 1 ms × j after the header stamp 1.7e9 + 0.1 k s
// (nanoseconds that a double cannot hold in seconds exactly are avoided), logged 1 µs after its stamp.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "cloud_writer.hpp"
#include "recording_message.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::test {

inline constexpr std::int64_t kFirstStampNs = 1700000000000000000;
inline constexpr std::int64_t kScanPeriodNs = 100000000;  ///< 10 Hz

inline std::int64_t stamp_ns(std::size_t k) {
  return kFirstStampNs + static_cast<std::int64_t>(k) * kScanPeriodNs;
}

/// The cloud of scan k (fields x y z intensity t).
inline TestCloud known_cloud(std::size_t k, std::size_t points = 5) {
  std::vector<std::vector<double>> values;
  for (std::size_t j = 0; j < points; ++j)
    values.push_back({static_cast<double>(k) + 0.5 * static_cast<double>(j), -static_cast<double>(j),
                      0.25 * static_cast<double>(k), static_cast<double>(j), 1e6 * static_cast<double>(j)});
  TestCloud c = make_test_cloud(xyz_intensity_t_fields(), values);
  c.sec = static_cast<std::int32_t>(stamp_ns(k) / 1000000000);
  c.nsec = static_cast<std::uint32_t>(stamp_ns(k) % 1000000000);
  return c;
}

/// Scan k as a message of `topic`: ROS 1 serialization when `ros1`, else CDR.
inline TestMessage known_message(std::size_t k, bool ros1, const std::string& topic = "/points",
                                 std::size_t points = 5) {
  const TestCloud c = known_cloud(k, points);
  return TestMessage{topic, ros1 ? "sensor_msgs/PointCloud2" : "sensor_msgs/msg/PointCloud2",
                     stamp_ns(k) + 1000, ros1 ? serialize_ros1(c) : serialize_cdr(c)};
}

/// `n` scans of `topic`, and between them messages of another topic (not point clouds).
inline std::vector<TestMessage> known_messages(std::size_t n, bool ros1, const std::string& topic = "/points",
                                               std::size_t points = 5) {
  std::vector<TestMessage> messages;
  for (std::size_t k = 0; k < n; ++k) {
    messages.push_back(known_message(k, ros1, topic, points));
    messages.push_back(TestMessage{"/chatter", ros1 ? "std_msgs/String" : "std_msgs/msg/String",
                                   stamp_ns(k) + 50000000, Bytes{0, 1, 0, 0, 2, 0, 0, 0, 'h', 0}});
  }
  return messages;
}

/// The cloud read back is scan k, exactly (float32 values, times of a float).
inline void expect_known_scan(const PointCloud& cloud, std::size_t k, std::size_t points = 5) {
  ASSERT_EQ(cloud.size(), points - (k == 0 ? 1 : 0)) << "scan " << k;  // scan 0's point 0 is (0, 0, 0)
  ASSERT_TRUE(cloud.has_intensity());
  ASSERT_TRUE(cloud.has_time());
  const std::size_t first = k == 0 ? 1 : 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double j = static_cast<double>(i + first);
    EXPECT_EQ(cloud[i].x(), static_cast<float>(static_cast<double>(k) + 0.5 * j)) << k << " " << i;
    EXPECT_EQ(cloud[i].y(), static_cast<float>(-j));
    EXPECT_EQ(cloud[i].z(), static_cast<float>(0.25 * static_cast<double>(k)));
    EXPECT_EQ(cloud.intensity()[i], static_cast<float>(j));
    EXPECT_FLOAT_EQ(cloud.time()[i], static_cast<float>(1e-3 * j));
  }
}

}  // namespace sextant::test
