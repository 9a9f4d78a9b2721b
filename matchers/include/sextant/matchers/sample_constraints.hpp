#pragma once
// Does a feature sample constrain all six pose parameters? FbML-NDT matches only plane inliers
// (Table 3.2); a scan whose planes are all parallel to one axis (a corridor, the ground alone, two
// walls) leaves a translation or rotation unobservable, and ML-NDT then drifts along it unchecked.
// The check builds the point-to-plane information of the sample,
//   A = Σ_i J_iᵀ J_i,  J_i = [ n_iᵀ , ((p_i − c) × n_i)ᵀ / r ],
// (c the sample's centroid, r its RMS radius, so that translations and rotations are comparable)
// and calls the sample degenerate when its weakest direction carries too small a share of the
// strongest (the degeneracy measure of Zhang, Kaess and Singh, ICRA 2016), or when there are too few
// planes, inliers or normal directions.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/point_cloud.hpp"
#include "sextant/features/landmark.hpp"

namespace sextant {

struct ConstraintThresholds {
  std::size_t min_planes = 3;       ///< cell planes in the sample [count]
  std::size_t min_inliers = 200;    ///< plane inliers in the sample [count]
  double min_normal_spread = 0.01;  ///< smallest eigenvalue share of Σ n nᵀ / N: three directions [0, 1/3]
  double min_information_ratio = 1e-3;  ///< λ_min / λ_max of A [0, 1]
  bool valid(std::string* why) const;
};

struct ConstraintCheck {
  std::size_t planes = 0, inliers = 0;
  Eigen::Vector3d normal_spread = Eigen::Vector3d::Zero();  ///< eigenvalues of Σ n nᵀ / N, ascending
  double information_ratio = 0.0;                           ///< λ_min / λ_max of A
  Eigen::Matrix<double, 6, 1> weakest_direction = Eigen::Matrix<double, 6, 1>::Zero();  ///< [t; r] of λ_min
  bool constrains_all = false;
  std::string reason;  ///< why not, e.g. "normals span fewer than three directions (0.0003)"
};

/// Checks the cell planes of `cloud` (their `inliers` index the cloud).
ConstraintCheck check_plane_constraints(const std::vector<PlaneLandmark>& planes, const PointCloud& cloud,
                                        const ConstraintThresholds& thresholds);

}  // namespace sextant
