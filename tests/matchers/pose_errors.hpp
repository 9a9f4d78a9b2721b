#pragma once
// Poses in degrees and the error of an estimated transform, for the matcher tests.
#include <cmath>

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

}  // namespace sextant::test
