#include "sextant/eval/umeyama.hpp"

#include <Eigen/SVD>

namespace sextant {

// Umeyama, "Least-squares estimation of transformation parameters between two point patterns",
// PAMI 1991, eqs. (34)–(42).
Similarity3 umeyama_alignment(const std::vector<Eigen::Vector3d>& src,
                              const std::vector<Eigen::Vector3d>& dst, bool with_scale) {
  Similarity3 out;
  const std::size_t n = src.size();
  if (n < 2 || dst.size() != n) {
    out.ok = false;
    return out;
  }
  Eigen::Vector3d mean_src = Eigen::Vector3d::Zero(), mean_dst = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (!src[i].allFinite() || !dst[i].allFinite()) {
      out.ok = false;
      return out;
    }
    mean_src += src[i];
    mean_dst += dst[i];
  }
  mean_src /= static_cast<double>(n);
  mean_dst /= static_cast<double>(n);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  double variance_src = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d a = src[i] - mean_src, b = dst[i] - mean_dst;
    covariance += b * a.transpose();
    variance_src += a.squaredNorm();
  }
  covariance /= static_cast<double>(n);
  variance_src /= static_cast<double>(n);
  if (variance_src < 1e-18) {
    out.ok = false;
    return out;
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d d = svd.singularValues();
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  // Collinear points leave the rotation about their line free; any such rotation fits equally well.
  out.rotation = svd.matrixU() * S * svd.matrixV().transpose();
  out.scale = with_scale ? (d.asDiagonal() * S).trace() / variance_src : 1.0;
  out.translation = mean_dst - out.scale * out.rotation * mean_src;
  return out;
}

}  // namespace sextant
