#pragma once
// Least-squares similarity between two point sets (Umeyama 1991): the s, R, t minimising
// Σ ‖dst_i − (s·R·src_i + t)‖², with det R = +1.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sextant {

struct Similarity3 {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;
  bool ok = true;  ///< false for fewer than 2 points, different sizes, non-finite input or coincident points

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return scale * (rotation * p) + translation; }
};

/// With `with_scale` false the scale is fixed at 1 (SE(3) alignment). Degenerate input returns
/// the identity with ok = false.
Similarity3 umeyama_alignment(const std::vector<Eigen::Vector3d>& src,
                              const std::vector<Eigen::Vector3d>& dst, bool with_scale);

}  // namespace sextant
