#include "sextant/filters/covariance.hpp"

#include <Eigen/Cholesky>

namespace sextant {

Eigen::MatrixXd symmetrized(const Eigen::MatrixXd& P) {
  return 0.5 * (P + P.transpose());
}

bool is_positive_definite(const Eigen::MatrixXd& P) {
  if (P.rows() != P.cols() || !P.allFinite()) return false;
  Eigen::LLT<Eigen::MatrixXd> llt(P);
  return llt.info() == Eigen::Success;
}

bool cholesky_lower(const Eigen::MatrixXd& P, Eigen::MatrixXd* L) {
  if (P.rows() != P.cols() || !P.allFinite()) return false;
  Eigen::LLT<Eigen::MatrixXd> llt(P);
  if (llt.info() != Eigen::Success) return false;
  *L = llt.matrixL();
  return L->allFinite();
}

Eigen::MatrixXd block_diagonal(const Eigen::MatrixXd& block, int count) {
  const Eigen::Index r = block.rows(), c = block.cols();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(r * count, c * count);
  for (int i = 0; i < count; ++i) out.block(i * r, i * c, r, c) = block;
  return out;
}

}  // namespace sextant
