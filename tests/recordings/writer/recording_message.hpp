#pragma once
// Test-only: one message a test writes into a recording.
#include <cstdint>
#include <string>

#include "byte_writer.hpp"

namespace sextant::test {

struct TestMessage {
  std::string topic;
  std::string type;  ///< "sensor_msgs/PointCloud2" (ROS 1) or "sensor_msgs/msg/PointCloud2" (ROS 2), …
  std::int64_t log_time = 0;  ///< [ns]
  Bytes data;                 ///< serialized as the container's encoding expects
};

/// Compresses `data` as bz2, lz4 (frame format) or zstd with Debian's libraries; any other name ("none",
/// "", or one to test that readers refuse it): a copy.
Bytes compress(const std::string& compression, const Bytes& data);

}  // namespace sextant::test
