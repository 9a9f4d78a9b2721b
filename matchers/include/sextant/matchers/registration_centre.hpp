#pragma once
// The point a registration turns about. A registration turns the input about the origin of its
// coordinates: the sensor, in a scan's own frame. Clouds far from that origin (georeferenced, or
// exported in a map frame) would turn about a point hundreds of metres or kilometres away, where a
// thousandth of a degree moves them by centimetres: the registration ends metres off or degenerate
// (docs/bad_input.md). Such clouds are registered in a frame centred at the reference, and the
// transforms are brought back:
//
//   const CentredFrame frame(registration_centre(reference));
//   T_local = register(frame.cloud(reference), frame.cloud(input), frame.local(guess));
//   T = frame.coordinates(T_local);
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"

namespace sextant {

/// The origin of the coordinates when a sensor could stand there (inside the reference's bounding box,
/// or no farther from it than a tenth of the box's diagonal), else the centre of the box.
Eigen::Vector3d registration_centre(const PointCloud& reference);

/// The clouds' coordinates moved by −centre. A transform T of the coordinates (p_ref = T·p_input)
/// is C⁻¹·T·C there, with C the translation by `centre`.
class CentredFrame {
 public:
  explicit CentredFrame(const Eigen::Vector3d& centre = Eigen::Vector3d::Zero())
      : centre_(centre), to_coordinates_(Eigen::Translation3d(centre)) {}
  const Eigen::Vector3d& centre() const { return centre_; }
  /// Whether this frame differs from the coordinates (centre ≠ 0).
  bool moved() const { return !centre_.isZero(); }
  PointCloud cloud(const PointCloud& c) const { return c.transformed(to_coordinates_.inverse()); }
  Eigen::Isometry3d local(const Eigen::Isometry3d& T) const {
    return to_coordinates_.inverse() * T * to_coordinates_;
  }
  Eigen::Isometry3d coordinates(const Eigen::Isometry3d& T) const {
    return to_coordinates_ * T * to_coordinates_.inverse();
  }
  /// A Hessian over ξ (eq. 3.12) of local(T), as one over ξ of T: Jᵀ·H·J with J = ∂ξ_local/∂ξ. The
  /// angles are the same; the translation moves with the rotation, t_local = t + (R − I)·c.
  Matrix6d hessian_in_coordinates(const Matrix6d& H_local, const Eigen::Isometry3d& T) const;

 private:
  Eigen::Vector3d centre_;
  Eigen::Isometry3d to_coordinates_;
};

}  // namespace sextant
