#pragma once
// Trajectory files that evo and the KITTI devkit read:
//  - TUM: one pose per line, "timestamp tx ty tz qx qy qz qw" (metres, Hamilton quaternion,
//    world ← body); '#' lines are comments. A trajectory is in time order: the poses are read
//    sorted by their stamps (how many lines were out of order is reported), and a stamp given twice
//    is an error naming both lines.
//  - KITTI: one 3×4 row-major world ← body matrix per line (12 numbers), no time; read stamps
//    are the line index 0, 1, 2, …
// Writers write atomically with 9 significant digits.
#include <cstddef>
#include <filesystem>
#include <string>

#include "sextant/core/trajectory.hpp"

namespace sextant {

/// What reading a trajectory file changed about it.
struct TrajectoryReadNotes {
  std::size_t out_of_order = 0;  ///< lines whose stamp is before an earlier line's (sorted by stamp)
};

/// The note a user reads for `notes` of `file` ("" when there is nothing to say).
std::string trajectory_note(const std::filesystem::path& file, const TrajectoryReadNotes& notes);

Trajectory read_tum_trajectory(const std::filesystem::path& file, TrajectoryReadNotes* notes = nullptr);
void write_tum_trajectory(const std::filesystem::path& file, const Trajectory& trajectory);

Trajectory read_kitti_trajectory(const std::filesystem::path& file);
void write_kitti_trajectory(const std::filesystem::path& file, const Trajectory& trajectory);

enum class TrajectoryFormat { kTum, kKitti };
/// The format of a trajectory file from its first data line: 8 numbers TUM, 12 KITTI; InputError
/// naming the line otherwise (and for a file without poses).
TrajectoryFormat detect_trajectory_format(const std::filesystem::path& file);
/// Reads a TUM or KITTI file, whichever detect_trajectory_format finds.
Trajectory read_trajectory(const std::filesystem::path& file, TrajectoryReadNotes* notes = nullptr);

}  // namespace sextant
