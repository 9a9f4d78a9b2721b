#pragma once
// KITTI odometry files (see docs/formats.md): velodyne scans `.bin` (little-endian float32
// x y z intensity, 16 bytes per point) and the 12-byte `.xyz32.bin` variant (x y z), the
// camera-0 poses file (one 3×4 row-major matrix per line), `calib.txt` (the `Tr:` line maps
// Velodyne points into camera 0), and `times.txt` (one time [s] per scan).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// `.bin`, 16 bytes per point (x y z intensity). A size that is not a multiple of 16 is an
/// InputError naming the byte offset of the incomplete point. Non-finite points are dropped
/// and counted.
PointCloud read_kitti_velodyne(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
/// Writes x y z and the intensity (0 when the cloud has none).
void write_kitti_velodyne(const std::filesystem::path& file, const PointCloud& cloud);

/// `.xyz32.bin`, 12 bytes per point (x y z).
PointCloud read_xyz32(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
void write_xyz32(const std::filesystem::path& file, const PointCloud& cloud);

/// One 3×4 row-major matrix per line (12 numbers), e.g. poses/00.txt: world(cam0 at t0) ← cam0(t).
std::vector<Eigen::Isometry3d> read_kitti_poses(const std::filesystem::path& file);
void write_kitti_poses(const std::filesystem::path& file, const std::vector<Eigen::Isometry3d>& poses);

/// The `Tr:` line of a calib file (cam0 ← velodyne). InputError when absent.
Eigen::Isometry3d read_kitti_calib_tr(const std::filesystem::path& file);

/// Velodyne-frame poses: Tr⁻¹ · P0⁻¹ · Pi · Tr, so the first is the identity and the relative
/// pose between i and j is Tr⁻¹ · Pi⁻¹ · Pj · Tr.
std::vector<Eigen::Isometry3d> kitti_velodyne_poses(const std::vector<Eigen::Isometry3d>& camera_poses,
                                                    const Eigen::Isometry3d& Tr);

/// What is wrong with a scan's time `time` [s] after the previous scan's (none for the first scan), in
/// words; "" when nothing is. Scan times are finite and each after the one before: every reader of them
/// (times.txt, the Python module's `times`) holds them to this.
std::string scan_time_problem(std::optional<double> previous, double time);

/// `times.txt`: one time [s] per line.
std::vector<double> read_kitti_times(const std::filesystem::path& file);

}  // namespace sextant
