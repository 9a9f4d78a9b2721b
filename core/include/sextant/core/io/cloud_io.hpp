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
/// The points of a written file that reading it back drops (written all the same: another tool may
/// keep them), so that a conversion that cannot keep a point says so.
struct CloudWriteReport {
  std::size_t points = 0;      ///< written
  std::size_t non_finite = 0;  ///< NaN/Inf coordinates: every reader drops them
  /// `.3d` only: points at or beyond 32.75 m, which a uos reader takes for the SICK's "no return"
  std::size_t beyond_no_return_range = 0;
  /// The cloud's per-point times were not written: only `.pcd` and `.ply` keep them
  bool times_dropped = false;
  std::size_t dropped_on_reading() const { return non_finite + beyond_no_return_range; }
};

/// Writes atomically; the format follows the extension. An empty cloud is written as such.
CloudWriteReport write_cloud(const std::filesystem::path& file, const PointCloud& cloud);

/// "1098 of 12998 points written to FILE lie at or beyond 32.75 m: a .3d reader takes them for the
/// SICK's 'no return' and drops them (…)", or empty when reading the file back gives every point (and
/// its time, when it has one).
std::string dropped_on_reading_note(const std::filesystem::path& file, const CloudWriteReport& report);

}  // namespace sextant
