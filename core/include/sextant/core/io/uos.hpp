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
/// The uos pose matrix of a `.pose` file: rotation Rx(θx)·Ry(θy)·Rz(θz) (eq. 3.8, 3DTK's
/// EulerToMatrix4) and translation t [cm], both in the uos frame.
Eigen::Matrix4d uos_euler_to_matrix(const Eigen::Vector3d& t_cm, const Eigen::Vector3d& theta_rad);

/// Points at or beyond this range from the scanner origin are the "no return" sentinel
/// (the SICK's 32.76 m maximum; docs/formats.md, "uos `.3d` details").
constexpr double kUosNoReturnRangeCm = 3275.0;
bool is_uos_no_return(const Eigen::Vector3d& p_uos_cm);
/// Type code written as the 17th number of each `.frames` line (3DTK reads and ignores it here).
constexpr int kUosFrameTypeCode = 0;

/// Reads a `.3d` file: skips header lines (lines among the first two, before any point, that are
/// not ≥ 3 numbers, e.g. "360 x 225"), drops and counts "no return" (range ≥ 3275 cm) and
/// non-finite points; malformed numbers are an InputError with the line. A 4th column, when
/// every line has one, is read as intensity. report->points_read counts every point line.
PointCloud read_uos_scan(const std::filesystem::path& file, ScanLoadReport* report = nullptr);
void write_uos_scan(const std::filesystem::path& file, const PointCloud& cloud);

/// `.pose`: the world ← scan pose in the internal frame.
Eigen::Isometry3d read_uos_pose(const std::filesystem::path& file);
void write_uos_pose(const std::filesystem::path& file, const Eigen::Isometry3d& pose);

/// `.frames`: every matrix of the file, internal frame; the last one is the final registration.
std::vector<Eigen::Isometry3d> read_uos_frames(const std::filesystem::path& file);
void write_uos_frames(const std::filesystem::path& file, const std::vector<Eigen::Isometry3d>& frames);

}  // namespace sextant
