#pragma once
// Private: the per-format readers and writers behind read_cloud / write_cloud.
#include <filesystem>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::detail {

/// Text point lists: x y z [intensity] separated by commas or whitespace; a first line that is not
/// numbers (e.g. "x,y,z") is a header.
PointCloud read_point_list(const std::filesystem::path& file, ScanLoadReport* report);
/// `with_header_and_commas`: CSV ("x,y,z[,intensity]" header, comma-separated); otherwise spaces.
void write_point_list(const std::filesystem::path& file, const PointCloud& cloud,
                      bool with_header_and_commas);

/// PCD and PLY: our own readers (headers checked against the file size; a per-point time field under a
/// driver's name kept, point_time.hpp), PCL writers (a cloud's per-point time as the float field `time`).
PointCloud read_pcd(const std::filesystem::path& file, ScanLoadReport* report);
void write_pcd(const std::filesystem::path& file, const PointCloud& cloud);
PointCloud read_ply(const std::filesystem::path& file, ScanLoadReport* report);
void write_ply(const std::filesystem::path& file, const PointCloud& cloud);

}  // namespace sextant::detail
