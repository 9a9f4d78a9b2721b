#pragma once
// Private: sensor_msgs/PointCloud2 decoded from either serialization. ROS 1: little-endian, packed, a
// string is a u32 length and its bytes. CDR (ROS 2): a 4-byte encapsulation header (0x0000 big-endian,
// 0x0001 little-endian; 0x0006/0x0007 plain XCDR2), then the message, each value aligned to its size
// counted from the first byte after that header, a string's u32 length counting its closing NUL.
//   header (ROS 1: u32 seq, u32 sec, u32 nsec; ROS 2: i32 sec, u32 nanosec), string frame_id,
//   u32 height, u32 width, PointField[] fields (string name, u32 offset, u8 datatype, u32 count),
//   bool is_bigendian, u32 point_step, u32 row_step, u8[] data, bool is_dense
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "byte_cursor.hpp"
#include "container.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::recordings_detail {

struct PointField2 {
  std::string name;
  std::uint32_t offset = 0;
  std::uint8_t datatype = 0;  ///< 1 int8, 2 uint8, 3 int16, 4 uint16, 5 int32, 6 uint32, 7 float32, 8 float64
  std::uint32_t count = 1;
};

struct PointCloud2Message {
  double stamp = 0.0;  ///< the header's stamp [s]
  std::string frame_id;
  std::uint32_t height = 0, width = 0, point_step = 0, row_step = 0;
  bool is_bigendian = false, is_dense = false;
  std::vector<PointField2> fields;
  std::size_t data_offset = 0, data_size = 0;  ///< the point data, in the payload
};

/// "float32" for 7, …; "datatype 9" for a value that is none of them.
std::string datatype_name(std::uint8_t datatype);
/// 1, 2, 4 or 8 bytes; 0 for an unknown datatype.
std::size_t datatype_size(std::uint8_t datatype);

/// The message in `payload`; InputError at `place` (the payload's first byte) when it is malformed:
/// truncated, an unknown CDR representation, fields outside point_step, data shorter than the rows.
PointCloud2Message parse_point_cloud2(const Bytes& payload, MessageEncoding encoding, const Place& place);
/// The header's stamp [s] alone, from the payload's first 16 bytes or more.
double point_cloud2_stamp(const Bytes& payload_prefix, MessageEncoding encoding, const Place& place);

/// The points: x, y, z (float32 or float64), `intensity` when there is one, the per-point time field
/// (point_time.hpp) relative to the header's stamp. A point with a non-finite x, y, z or intensity is
/// dropped as non-finite, a point at exactly (0, 0, 0) as no-return (an organised scan's empty cell),
/// each counted in `report` (points_read: height × width).
PointCloud point_cloud2_points(const PointCloud2Message& message, const Bytes& payload, const Place& place,
                               ScanLoadReport* report);

}  // namespace sextant::recordings_detail
