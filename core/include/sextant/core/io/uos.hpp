#pragma once
// The uos format of the Osnabrück Robotic 3D Scan Repository (hannover1 layout), see
// data/README.md: `.3d` ASCII x y z in cm (left-handed, y up, z forward, x right), `.pose`
// (x y z cm / θx θy θz deg, R = Rx·Ry·Rz), `.frames` (4×4 column-major per line, last = final).
// Every reader converts to the internal frame (right-handed metres, x forward, y left, z up);
// every writer converts back.
#include <filesystem>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// uos point [cm, left-handed y-up] → internal [m]: x = z/100, y = −x/100, z = y/100.
Eigen::Vector3d uos_to_internal(const Eigen::Vector3d& p_uos_cm);
Eigen::Vector3d internal_to_uos(const Eigen::Vector3d& p_m);
/// A uos pose matrix (cm, left-handed) ↔ the same pose in the internal frame.
Eigen::Isometry3d uos_pose_to_internal(const Eigen::Matrix4d& T_uos);
Eigen::Matrix4d internal_pose_to_uos(const Eigen::Isometry3d& T);

/// Reads a `.3d` file: skips up to a few header lines, drops and counts "no return" (3276 cm)
/// and non-finite points; malformed numbers are an InputError with the line.
PointCloud read_uos_scan(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
void write_uos_scan(const std::filesystem::path& file, const PointCloud& cloud);

/// `.pose`: the world ← scan pose in the internal frame.
Eigen::Isometry3d read_uos_pose(const std::filesystem::path& file);
void write_uos_pose(const std::filesystem::path& file, const Eigen::Isometry3d& pose);

/// `.frames`: every matrix of the file, internal frame; the last one is the final registration.
std::vector<Eigen::Isometry3d> read_uos_frames(const std::filesystem::path& file);
void write_uos_frames(const std::filesystem::path& file, const std::vector<Eigen::Isometry3d>& frames);

}  // namespace sextant
