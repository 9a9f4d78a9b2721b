#pragma once
// Point-cloud files by extension: `.3d` (uos), `.bin` (KITTI velodyne, 16 bytes x y z i),
// `.xyz32.bin` (12 bytes x y z), `.pcd` and `.ply` (PCL io), `.csv`/`.xyz`/`.txt` (x,y,z[,i]).
// Every reader converts to the internal frame and drops+counts non-finite points.
#include <filesystem>
#include <string>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// What a file extension means.
struct CloudFormat {
  std::string extension;  ///< e.g. ".xyz32.bin"
  std::string name;       ///< e.g. "KITTI velodyne xyz float32"
  std::string frame;      ///< the file's frame and units, and what the reader does to them
};

/// The format of `file` by its extension (case-insensitive); InputError for an unknown one.
CloudFormat cloud_format(const std::filesystem::path& file);
/// Every known format.
std::vector<CloudFormat> cloud_formats();

/// Reads any known format. A file that holds no usable point (empty, or every point dropped) is
/// an InputError, as is every malformed input (with the line or byte offset).
PointCloud read_cloud(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
/// Writes atomically; the format follows the extension. An empty cloud is written as such.
void write_cloud(const std::filesystem::path& file, const PointCloud& cloud);

}  // namespace sextant
