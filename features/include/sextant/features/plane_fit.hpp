#pragma once
// Plane fitting to a point set (§3.3.1.1): the SVD of the constraint matrix [x y z 1]
// (eqs. (3.22)–(3.25)) or PCA of the points (normal = smallest principal axis), and the first
// and second moments (count, centroid, scatter) that merging combines without the points.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/enum_names.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/features/plane.hpp"

namespace sextant {

/// Count, centroid and scatter Σ(p−c)(p−c)ᵀ of a point set; two sets combine exactly.
struct PointMoments {
  std::size_t count = 0;                               ///< k [points]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< centre of gravity [m]
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();   ///< Σ(p−c)(p−c)ᵀ [m²]

  /// Sample covariance scatter/(k−1), eq. (3.28); zero for k < 2.
  Eigen::Matrix3d covariance() const;
  void add(const Eigen::Vector3d& p);  ///< Welford update
  /// The moments of the union of two disjoint point sets.
  static PointMoments combine(const PointMoments& a, const PointMoments& b);
  /// From a covariance (eq. (3.28) convention) and a count.
  static PointMoments from_covariance(std::size_t count, const Eigen::Vector3d& centroid,
                                      const Eigen::Matrix3d& covariance);
};

PointMoments compute_moments(PointsView points, const std::vector<std::size_t>& indices);
PointMoments compute_moments(const std::vector<Eigen::Vector3d>& points);

enum class PlaneRefit {
  pca,  ///< covariance eigen-decomposition, normal = smallest principal axis (§3.3.1.1)
  svd   ///< SVD of A = [x y z 1], β = last right-singular vector, eqs. (3.23)–(3.25)
};

inline constexpr EnumNames<PlaneRefit, 2> kPlaneRefitNames{
    "plane refit", {{{PlaneRefit::pca, "pca"}, {PlaneRefit::svd, "svd"}}}};
bool from_string(const std::string& text, PlaneRefit* out);
std::string to_string(PlaneRefit refit);

struct PlaneFit {
  bool ok = false;                                        ///< false for < 3 points or a degenerate set
  Plane plane;                                            ///< n·x = d, |n| = 1
  PointMoments moments;                                   ///< of the fitted points
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();  ///< of the covariance, ascending [m²]
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();     ///< principal axes (columns), ascending
};

/// PCA fit from moments (normal = eigenvector of the smallest eigenvalue); ok = false when the
/// second eigenvalue is not positive (points on a line or a single point).
PlaneFit fit_plane_pca(const PointMoments& moments);
PlaneFit fit_plane(PointsView points, const std::vector<std::size_t>& indices, PlaneRefit method);

/// Orients the plane so its normal points towards `viewpoint` (n·(v − c) ≥ 0, d = n·c).
void orient_towards(Plane& plane, const Eigen::Vector3d& viewpoint);

}  // namespace sextant
