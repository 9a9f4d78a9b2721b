#pragma once
// Internal to the score kernels (ndt_score.cpp, mahalanobis_kernel.cpp): the per-block sums.
#include <cstddef>

#include <Eigen/Core>

#include "sextant/core/pose.hpp"

namespace sextant::score_detail {

/// Weighted sums in "pre-A" coordinates, where the point Jacobian is J' = [I, −[u]×].
/// P and S are symmetric: only their upper triangles are summed (mirrored in finish()).
struct Sums {
  double score = 0.0;
  Eigen::Vector3d g_t = Eigen::Vector3d::Zero();  ///< Σ w·C⁻¹e
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();  ///< Σ w·C⁻¹e·uᵀ (gives Σ w·u × C⁻¹e and 2nd-order terms)
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();  ///< Σ w·C⁻¹
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();  ///< Σ w·C⁻¹[u]×
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();  ///< Σ w·[u]×ᵀC⁻¹[u]×
  Matrix6d outer = Matrix6d::Zero();  ///< Σ v·m·mᵀ, m = [C⁻¹e; u × C⁻¹e] (Gaussian score)
  std::size_t matched = 0;
  std::size_t rejected = 0;
};

/// total += block, term by term.
inline void add(Sums& total, const Sums& block) {
  total.score += block.score;
  total.g_t += block.g_t;
  total.N += block.N;
  total.P += block.P;
  total.Q += block.Q;
  total.S += block.S;
  total.outer += block.outer;
  total.matched += block.matched;
  total.rejected += block.rejected;
}

}  // namespace sextant::score_detail
