#pragma once
// A scan matcher's relative pose as the control of the plane-SLAM vehicle model (hybrid SLAM, the
// thesis' future work §7.2, E21). The matcher gives T (previous scan ← current scan) with the
// covariance Σ = H⁻¹ of its parameters p = (t_x, t_y, t_z, α, β, γ), R(p) = Rx(α)·Ry(β)·Rz(γ)
// (eqs. 3.8, 3.50). The vehicle model (eq. 4.72) moves the pose x = (t, o) by u = (δt, δo):
//   t' = t + R(o)·δt,  o' = o + δo.
// The new pose is (t + R(o)·t_T, euler(R(o)·R_T)), so the control that reproduces it exactly is
//   δt = t_T,  δo = euler(R(o)·R(a_T)) − o   (wrapped),
// and Q = J·Σ·Jᵀ with J = ∂u/∂p = [[I, 0], [0, ∂δo/∂a]] (δt does not depend on the angles, δo not
// on the translation). ∂δo/∂a depends on the orientation o the increment starts from (the filter's
// estimate): Euler differences are not rotation increments; it is the identity only at o = 0. It is
// taken by central differences (the angles are far from the gimbal lock β = ±π/2 on ground vehicles).
// The matcher's estimate is treated as a control (independent of the filter's state); that
// consecutive registrations share a scan, and so correlate, is ignored, as with the odometry.
#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"

namespace sextant {

struct MotionIncrement {
  Vector6d u = Vector6d::Zero();  ///< control of eq. (4.72)
  Matrix6d Q = Matrix6d::Zero();  ///< its covariance
};

/// ∂u/∂p at the pose `from` (x, y, z, α, β, γ) for the relative pose p = (t, α, β, γ).
Matrix6d relative_pose_jacobian(const Vector6d& from, const Vector6d& relative);

/// The control and its covariance for the relative pose T (previous ← current) with covariance Σ
/// over p, applied at the pose `from`.
MotionIncrement increment_from_relative_pose(const Vector6d& from, const Eigen::Isometry3d& relative,
                                             const Matrix6d& covariance);

}  // namespace sextant
