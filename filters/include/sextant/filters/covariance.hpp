#pragma once
// Covariance health checks shared by every filter: a failed Cholesky is a status, not a crash.
#include <Eigen/Core>

namespace sextant {

/// (P + Pᵀ)/2.
Eigen::MatrixXd symmetrized(const Eigen::MatrixXd& P);
/// True when P is symmetric positive definite (its LLᵀ factorisation succeeds).
bool is_positive_definite(const Eigen::MatrixXd& P);
/// Lower-triangular L with P = L·Lᵀ (Σ = chol(P)ᵀ, §4.2.2.1); false when P is not positive
/// definite or not finite (L is then left unspecified).
bool cholesky_lower(const Eigen::MatrixXd& P, Eigen::MatrixXd* L);
/// Block-diagonal matrix with `count` copies of `block` (stacked observation noise).
Eigen::MatrixXd block_diagonal(const Eigen::MatrixXd& block, int count);

}  // namespace sextant
