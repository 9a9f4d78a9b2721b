#pragma once
// A planar landmark (§4.1): infinite plane (n, d) plus the semantic data used by merging and
// data association — centre of gravity c, inlier covariance Σ, inlier count k, convex hull
// Δ_XYZ, area A — transformable between frames (eqs. (4.57)–(4.61)).
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sextant/features/hull.hpp"
#include "sextant/features/plane.hpp"
#include "sextant/features/plane_fit.hpp"

namespace sextant {

struct PlaneLandmark {
  Plane plane;                                           ///< n·x = d, normal towards the sensor
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();    ///< c [m]
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< Σ of the inliers, eq. (3.28) [m²]
  std::size_t inlier_count = 0;                          ///< k [points]
  double area = 0.0;                                     ///< A, from the hull [m²]
  std::vector<Eigen::Vector3d> hull;                     ///< Δ_XYZ, convex polygon on the plane [m]
  std::vector<Eigen::Vector3d> rectangle;                ///< min-area bounding rectangle (4 corners) [m]
  std::vector<std::size_t> inliers;  ///< indices into the extracted cloud (empty when not known)

  PointMoments moments() const { return PointMoments::from_covariance(inlier_count, centroid, covariance); }
  /// The landmark in another frame, p' = T·p: n' = R n, d' = d + n'·t, Σ' = R Σ Rᵀ, c' = R c + t,
  /// Δ' = R Δ + t (eqs. (4.57)–(4.61); eq. (4.59) as printed omits the Rᵀ). Inlier indices kept.
  PlaneLandmark transformed(const Eigen::Isometry3d& T) const;
};

std::vector<PlaneLandmark> transform_landmarks(const std::vector<PlaneLandmark>& landmarks,
                                               const Eigen::Isometry3d& T);

/// Builds a landmark from the fitted inliers of a point set: plane from `fit`, normal oriented
/// towards `viewpoint`, outline from the inlier points projected in their principal frame.
PlaneLandmark make_landmark(PointsView points, std::vector<std::size_t> inliers, const PlaneFit& fit,
                            const Eigen::Vector3d& viewpoint);

/// Angle between the normal and the up axis (z) folded to [0°, 90°] [deg]; 0 for a horizontal plane.
double tilt_from_horizontal_deg(const Plane& plane);

}  // namespace sextant
