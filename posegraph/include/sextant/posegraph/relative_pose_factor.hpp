#pragma once
// The SE(3) relative-pose factor of the pose graph (Lu–Milios' globally consistent n-scan
// registration, thesis §7.2). A node is the world ← scan pose T = (t, q): translation t ∈ ℝ³ and a
// unit quaternion q (Eigen's x, y, z, w order). An edge i → j measures the pose of j seen from i,
// T_ij* (e.g. a registration of scan j onto scan i). With the error transform
//
//   E = T_ij*⁻¹ · T_i⁻¹ · T_j        (identity when the graph agrees with the measurement)
//
// the residual is r = L · [t(E); log(R(E))], log the SO(3) log map (rotation vector, angle ≤ π)
// and L the upper Cholesky factor of the 6×6 information Ω (LᵀL = Ω), so rᵀr = eᵀΩe. The
// Jacobians are Ceres' automatic derivatives; tests/posegraph checks them against central
// differences.
#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"

namespace ceres {
class CostFunction;
}

namespace sextant {

/// The unweighted error e = [t(E); log(R(E))] of E = measured⁻¹ · T_i⁻¹ · T_j [m, rad].
Vector6d relative_pose_error(const Eigen::Isometry3d& measured, const Eigen::Isometry3d& T_i,
                             const Eigen::Isometry3d& T_j);

/// The Ceres cost of one edge: parameter blocks t_i (3), q_i (4), t_j (3), q_j (4), 6 residuals.
/// `sqrt_information` is L with LᵀL = Ω (see sqrt_information()). The caller owns the result
/// (Ceres' Problem takes ownership when it is added).
ceres::CostFunction* make_relative_pose_cost(const Eigen::Isometry3d& measured,
                                             const Matrix6d& sqrt_information);

/// L (upper triangular, LᵀL = Ω) of a symmetric positive-definite Ω; false when Ω is not finite or
/// not positive definite (then L is left untouched).
bool sqrt_information(const Matrix6d& information, Matrix6d* L);

/// The information of the factor's error e from the Hessian H of a registration score over the
/// Pose6 parameters ξ = (x, y, z, α, β, γ) of the relative pose (eq. 3.12): the registration's
/// covariance of ξ is R = H⁻¹ (eq. 3.50); e ≈ J·(ξ − ξ*) with J = ∂e/∂ξ at ξ* = `measured`
/// (central differences), so Ω = J⁻ᵀ·H·J⁻¹. H is symmetrised first.
Matrix6d information_from_pose6_hessian(const Matrix6d& H, const Eigen::Isometry3d& measured);

}  // namespace sextant
