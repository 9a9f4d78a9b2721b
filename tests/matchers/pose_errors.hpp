#pragma once
// Poses in degrees, the error of an estimated transform and transform files, for the matcher tests.
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant::test {

/// T from x, y, z [m] and α, β, γ [deg] (eq. 3.8).
inline Eigen::Isometry3d pose(double x, double y, double z, double a_deg, double b_deg, double g_deg) {
  return to_isometry(Pose6{x, y, z, a_deg * kRadPerDeg, b_deg * kRadPerDeg, g_deg * kRadPerDeg});
}

/// ‖t‖ of truth⁻¹·estimate [m].
inline double translation_error(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate) {
  return translation_norm(inverse(truth) * estimate);
}

/// Rotation angle of truth⁻¹·estimate [rad].
inline double rotation_error(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate) {
  return rotation_angle(inverse(truth) * estimate);
}

/// Rotation angle of truth⁻¹·estimate [deg].
inline double rotation_error_deg(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate) {
  return rotation_error(truth, estimate) / kRadPerDeg;
}

/// A 4 × 4 transform written as 16 numbers, row by row (data/velodyne_pair/fast_gicp_relative.txt);
/// the test fails when the file does not hold them.
inline Eigen::Isometry3d read_transform(const std::string& path) {
  std::ifstream in(path);
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  EXPECT_FALSE(in.fail()) << path << ": not 16 numbers";
  return Eigen::Isometry3d(M);
}

}  // namespace sextant::test
