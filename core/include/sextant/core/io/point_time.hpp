#pragma once
// The per-point time field of a lidar record, whatever driver wrote it, and its values in the one
// unit sextant keeps (PointCloud::time: seconds from the scan's stamp). Every reader of a record
// format with named fields (PCD, PLY, sensor_msgs/PointCloud2) finds the field and converts it here.
//
// Drivers' names and units (the field's scalar type decides the unit):
//   t            Ouster               uint32 ns from the scan's start
//   time         Velodyne, Unitree    float32 s from the scan's stamp
//   timestamp    Hesai, Robosense     float64 s since the epoch (livox_ros_driver2: float64 ns)
//   offset_time  Livox CustomMsg      uint32 ns from the frame's time base
//   time_offset, ts                   the same two conventions, seen in exports
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sextant {

/// The names above, in the order they are preferred when a record has several.
const std::vector<std::string>& point_time_field_names();

/// The index in `field_names` of the per-point time field, or nullopt when the record has none.
std::optional<std::size_t> find_point_time_field(const std::vector<std::string>& field_names);

/// What point_times_to_seconds did: how the raw values were read.
struct PointTimeConversion {
  bool absolute = false;  ///< the values were times since the epoch, made relative
  double seconds_per_unit = 1.0;
};

/// Raw values of the time field → seconds from the scan's stamp. An integer field is in
/// nanoseconds, a floating one in seconds, unless its values are too large for seconds since the
/// epoch (beyond 10^11 s, the year 5138), which makes them nanoseconds. Values beyond 10^8 s are
/// times since the epoch: made relative to `stamp` [s since the epoch] when the scan has one, else
/// to the earliest finite value. Non-finite raw values stay non-finite (remove_non_finite counts them).
std::vector<float> point_times_to_seconds(const std::vector<double>& raw, bool integer_field,
                                          std::optional<double> stamp, PointTimeConversion* how = nullptr);

}  // namespace sextant
