#pragma once
// Poses in RunRow::series and back: a rigid transform is 12 numbers, its 3×4 [R t] row-major.
#include <vector>

#include <Eigen/Geometry>

#include "sextant/eval/trajectory_metrics.hpp"

namespace sextant {

std::vector<double> isometry_to_series(const Eigen::Isometry3d& T);
/// NaN transform when the series is missing or malformed.
Eigen::Isometry3d series_to_isometry(const std::vector<double>& s);

/// A pose list as 12 numbers per pose, and back (a trailing partial pose is dropped).
std::vector<double> poses_to_series(const PoseList& poses);
PoseList series_to_poses(const std::vector<double>& series);

}  // namespace sextant
