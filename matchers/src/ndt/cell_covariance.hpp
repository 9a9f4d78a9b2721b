#pragma once
// A cell's information matrix: the inverse of its covariance with the small eigenvalues raised (the
// covariance inflation after eq. 3.11), from the eigenvalues alone, or from no eigenvalue at all.
#include <Eigen/Core>

namespace sextant {

/// The eigenvalues of a symmetric matrix (its upper triangle is read), ascending: the trigonometric
/// solution of the characteristic cubic of C − (tr C / 3) I, scaled to its largest entry, with the
/// angle's cosine and sine from a complex cube root by Halley's iteration (no libm call). Their error
/// is of the order of machine ε · max |λ|, and of √ε · max |λ| at a (nearly) repeated eigenvalue.
Eigen::Vector3d symmetric_eigenvalues(const Eigen::Matrix3d& C);

/// C'⁻¹ for a symmetric C = V Λ Vᵀ (its upper triangle is read), where C' = V Λ' Vᵀ raises every
/// eigenvalue below λ₂ / ratio to it (ratio ≥ 1). False, and `information` untouched, when C is not
/// finite or its largest eigenvalue λ₂ is not above 0 and at least `least_spread` (a cell without
/// spread).
///
/// The eigenvectors are never formed: a raised eigenvalue enters through its spectral projector
/// Pᵢ = Πⱼ≠ᵢ (C − λⱼ I) / (λᵢ − λⱼ) (Sylvester's formula), a polynomial in C and so symmetric, and C'
/// (whose condition number is at most ratio) is inverted by its cofactors. Every coefficient that
/// multiplies a projector is at most the gap it divides by, so the error in C' stays of the order of
/// machine ε · λ₂, however close the eigenvalues. Where no eigenvalue needs raising for certain,
/// because λ₀ ≥ det C / c₂ ≥ ‖C‖_F / ratio ≥ λ₂ / ratio (c₂ the sum of C's principal 2 × 2 minors,
/// all eigenvalues positive), C is inverted at once and no eigenvalue is computed.
bool cell_information(const Eigen::Matrix3d& C, double ratio, double least_spread,
                      Eigen::Matrix3d& information);

}  // namespace sextant
