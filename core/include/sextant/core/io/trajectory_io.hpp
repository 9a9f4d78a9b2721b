#pragma once
// Trajectory files that evo and the KITTI devkit read:
//  - TUM: one pose per line, "timestamp tx ty tz qx qy qz qw" (metres, Hamilton quaternion,
//    world ← body); '#' lines are comments.
//  - KITTI: one 3×4 row-major world ← body matrix per line (12 numbers), no time; read stamps
//    are the line index 0, 1, 2, …
// Writers write atomically with 9 significant digits.
#include <filesystem>

#include "sextant/core/trajectory.hpp"

namespace sextant {

Trajectory read_tum_trajectory(const std::filesystem::path& file);
void write_tum_trajectory(const std::filesystem::path& file, const Trajectory& trajectory);

Trajectory read_kitti_trajectory(const std::filesystem::path& file);
void write_kitti_trajectory(const std::filesystem::path& file, const Trajectory& trajectory);

enum class TrajectoryFormat { kTum, kKitti };
/// The format of a trajectory file from its first data line: 8 numbers TUM, 12 KITTI; InputError
/// naming the line otherwise (and for a file without poses).
TrajectoryFormat detect_trajectory_format(const std::filesystem::path& file);
/// Reads a TUM or KITTI file, whichever detect_trajectory_format finds.
Trajectory read_trajectory(const std::filesystem::path& file);

}  // namespace sextant
