#pragma once
// 6D SLAM over infinite-plane landmarks (§4.2, eqs. 4.54–4.58, 4.64, 4.72).
//   pose x_v = (x, y, z, α, β, γ) with R = Rx(α)·Ry(β)·Rz(γ) (eq. 3.8);
//   control u = (δx, δy, δz, δα, δβ, δγ), an odometry increment;
//   landmark m = (nᵂ, dᵂ) and observation z = (nᴸ, dᴸ), 4 numbers each.
// Plane convention: the project's Plane (n·p = d, features/plane.hpp). The thesis writes
// n·p + d = 0, so its eqs. (4.58)/(4.64) carry the opposite sign of d; the geometry is the same:
//   observation  nᴸ = Rᵀnᵂ,  dᴸ = dᵂ − nᵂ·t           (eq. 4.64 in our sign)
//   augmentation nᵂ = R nᴸ,  dᵂ = dᴸ + nᵂ·t           (eqs. 4.57–4.58 in our sign)
// Vehicle model (eq. 4.72): t' = t + R(o)·δt, o' = o + δo with R at the orientation the
// increment was measured from (the printed index k is read as k−1); see odometry_increment().
#include <array>

#include <Eigen/Core>

#include "sextant/core/pose.hpp"
#include "sextant/features/plane.hpp"
#include "sextant/filters/slam_model.hpp"

namespace sextant {

class PlaneSlamModel final : public SlamModel {
 public:
  std::string name() const override { return "plane6d"; }
  int pose_dim() const override { return 6; }
  int control_dim() const override { return 6; }
  int landmark_dim() const override { return 4; }
  int observation_dim() const override { return 4; }

  Eigen::VectorXd process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const override;
  Eigen::MatrixXd process_jacobian_pose(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const override;
  Eigen::MatrixXd process_jacobian_control(const Eigen::VectorXd& pose,
                                           const Eigen::VectorXd& u) const override;
  Eigen::VectorXd observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& landmark) const override;
  Eigen::MatrixXd observe_jacobian_pose(const Eigen::VectorXd& pose,
                                        const Eigen::VectorXd& landmark) const override;
  Eigen::MatrixXd observe_jacobian_landmark(const Eigen::VectorXd& pose,
                                            const Eigen::VectorXd& landmark) const override;
  Eigen::VectorXd augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const override;
  Eigen::MatrixXd augment_jacobian_pose(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const override;
  Eigen::MatrixXd augment_jacobian_observation(const Eigen::VectorXd& pose,
                                               const Eigen::VectorXd& z) const override;

  std::vector<int> pose_angles() const override { return {3, 4, 5}; }
  /// Flips (n, d) → (−n, −d) when the measured normal points against the predicted one.
  Eigen::VectorXd align_observation(const Eigen::VectorXd& z,
                                    const Eigen::VectorXd& predicted) const override;
  /// n ← n/‖n‖, d ← d/‖n‖.
  void normalize_landmark(Eigen::Ref<Eigen::VectorXd> landmark) const override;
};

/// ∂R/∂α, ∂R/∂β, ∂R/∂γ of R = Rx(α)·Ry(β)·Rz(γ).
std::array<Eigen::Matrix3d, 3> rotation_derivatives(double alpha, double beta, double gamma);

/// The control u that takes `from` to `to` under the vehicle model (4.72): its exact inverse.
Vector6d odometry_increment(const Pose6& from, const Pose6& to);
/// Plane ↔ landmark/observation vector (n, d).
Eigen::Vector4d plane_vector(const Plane& plane);
Plane plane_from_vector(const Eigen::Vector4d& v);

}  // namespace sextant
