#pragma once
// Test-only: sensor_msgs/PointCloud2 messages with known content, serialized as ROS 1 does
// (little-endian, packed) or as CDR (ROS 2: encapsulation header, aligned, either byte order), written
// from the message definition and the CDR rules (docs/formats.md), not from any ROS code.
#include <cstdint>
#include <string>
#include <vector>

#include "byte_writer.hpp"

namespace sextant::test {

struct TestField {
  std::string name;
  std::uint8_t datatype = 7;  ///< 1 int8 … 7 float32, 8 float64
};

/// A PointCloud2 message's content.
struct TestCloud {
  std::int32_t sec = 0;
  std::uint32_t nsec = 0;
  std::string frame_id = "lidar";
  std::uint32_t height = 1, width = 0;
  std::vector<TestField> fields;
  std::vector<std::uint32_t> offsets;  ///< of each field in a point
  bool is_bigendian = false;
  std::uint32_t point_step = 0, row_step = 0;
  Bytes data;
  bool is_dense = true;
};

/// A cloud of `values` (one row per point, one value per field, in the fields' order), `height` rows
/// (the points row by row), fields packed in order with `point_padding` bytes after each point and
/// `row_padding` after each row, the point data in big-endian order when `big_endian`.
TestCloud make_test_cloud(const std::vector<TestField>& fields,
                          const std::vector<std::vector<double>>& values, std::uint32_t height = 1,
                          bool big_endian = false, std::uint32_t point_padding = 0,
                          std::uint32_t row_padding = 0);

/// The message as ROS 1 serializes it (header seq 0).
Bytes serialize_ros1(const TestCloud& cloud);
/// As CDR: encapsulation 0x0001 (little-endian) or 0x0000 (big-endian), then the aligned message.
Bytes serialize_cdr(const TestCloud& cloud, bool big_endian = false);

/// x, y, z (float32), intensity (float32) and t (uint32 ns) for each point: the fields tests use most.
std::vector<TestField> xyz_intensity_t_fields();

}  // namespace sextant::test
