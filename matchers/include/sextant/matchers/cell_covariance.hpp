#pragma once
// The inverse of a cell covariance with its small eigenvalues raised (the covariance inflation
// after eq. 3.11), from the eigenvalues alone.
#include <Eigen/Core>

namespace sextant {

/// C'⁻¹, where C = V Λ Vᵀ is symmetric with ascending eigenvalues `l` (Λ) and C' = V Λ' Vᵀ with
/// Λ' = max(Λ, floor), for 0 < floor ≤ λ₂. The eigenvectors are never formed: a raised eigenvalue
/// enters through its spectral projector Pᵢ = Πⱼ≠ᵢ (C − λⱼ I) / (λᵢ − λⱼ) (Sylvester's formula), and
/// C' (whose condition number is at most λ₂ / floor) is inverted by its cofactors. Every coefficient
/// that multiplies a projector is at most the gap it divides by, so the error in C' stays of the
/// order of machine ε · λ₂, however close the eigenvalues.
Eigen::Matrix3d inflated_inverse(const Eigen::Matrix3d& C, const Eigen::Vector3d& l, double floor);

}  // namespace sextant
