#pragma once
// An infinite plane n·x = d with unit normal n (Hessian normal form), eq. (3.22).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sextant {

struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit normal
  double d = 0.0;                                     ///< signed distance of the plane from the origin [m]

  double signed_distance(const Eigen::Vector3d& p) const { return normal.dot(p) - d; }
  /// The plane expressed in another frame: points p' = T·p, eqs. (4.57)–(4.58).
  Plane transformed(const Eigen::Isometry3d& T) const;
};

}  // namespace sextant
