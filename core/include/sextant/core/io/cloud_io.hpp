#pragma once
// Point-cloud files by extension: `.3d` (uos), `.bin` (KITTI velodyne, 16 bytes x y z i),
// `.xyz32.bin` (12 bytes x y z), `.pcd` and `.ply` (PCL io), `.csv`/`.xyz`/`.txt` (x,y,z[,i]).
// Every reader converts to the internal frame and drops+counts non-finite points.
#include <filesystem>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant {

PointCloud read_cloud(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
/// Writes atomically; the format follows the extension. An empty cloud is written as such.
void write_cloud(const std::filesystem::path& file, const PointCloud& cloud);

}  // namespace sextant
