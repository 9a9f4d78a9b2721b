#include "sextant/filters/covariance.hpp"

#include <Eigen/Cholesky>

namespace sextant {

Eigen::MatrixXd symmetrized(const Eigen::MatrixXd& P) { return 0.5 * (P + P.transpose()); }

bool is_positive_definite(const Eigen::MatrixXd& P) {
  if (P.rows() != P.cols() || !P.allFinite()) return false;
  Eigen::LLT<Eigen::MatrixXd> llt(P);
  return llt.info() == Eigen::Success;
}

}  // namespace sextant
