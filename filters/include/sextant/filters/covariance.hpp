#pragma once
// Covariance health checks shared by every filter: a failed Cholesky is a status, not a crash.
#include <Eigen/Core>

namespace sextant {

/// (P + Pᵀ)/2.
Eigen::MatrixXd symmetrized(const Eigen::MatrixXd& P);
/// True when P is symmetric positive definite (its LLᵀ factorisation succeeds).
bool is_positive_definite(const Eigen::MatrixXd& P);

}  // namespace sextant
