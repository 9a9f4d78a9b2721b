#pragma once
// The two NDT objectives over a cell grid, with analytic derivatives in ξ = [tx ty tz α β γ]
// (eq. 3.12, R = Rx(α)·Ry(β)·Rz(γ), eq. 3.8). Both are minimised:
//   Mahalanobis (ML-NDT): f = Σ eᵀC⁻¹e, e = R·x + t − μ                         eqs. (3.10)–(3.18)
//   Gaussian (P2D-NDT):   f = Σ d1·exp(−d2/2 · eᵀC⁻¹e)   (Magnusson's score; d1 < 0) eq. (3.6)
// Points whose cell has no Gaussian are skipped (matched counts the others).
#include <cstddef>
#include <limits>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {

enum class Derivatives {
  kScore,     ///< score and matched count only
  kGradient,  ///< + gradient
  kHessian,   ///< + exact Hessian (eq. 3.15) and, for the Mahalanobis score, its Gauss–Newton part
};

struct ScoreEvaluation {
  double score = 0.0;
  Vector6d gradient = Vector6d::Zero();
  Matrix6d hessian = Matrix6d::Zero();       ///< exact second derivative, eq. (3.15)/(3.18)
  Matrix6d gauss_newton = Matrix6d::Zero();  ///< 2·Σ JᵀC⁻¹J (Mahalanobis only): the LM matrix of eq. (3.21)
  std::size_t matched = 0;
  std::size_t rejected = 0;  ///< in a cell but beyond the Mahalanobis limit (not in `matched`)
};

/// Outlier-mixture constants of Magnusson's Gaussian score (Magnusson 2009, eqs. 6.8–6.9):
/// c1 = 10(1 − outlier_ratio), c2 = outlier_ratio / cell_edge³, d3 = −log c2,
/// d1 = −log(c1 + c2) − d3, d2 = −2·log((−log(c1·e^(−1/2) + c2) − d3) / d1).
struct GaussianScoreParams {
  double d1 = -1.0;
  double d2 = 1.0;
  static GaussianScoreParams from_outlier_ratio(double outlier_ratio, double cell_edge);
};

/// Σ eᵀC⁻¹e over `input` mapped by ξ, eqs. (3.11), (3.17), (3.18). Correspondences with
/// eᵀC⁻¹e > `max_distance` are rejected (counted in `rejected`, no score or derivative terms);
/// the default keeps all of them, as the thesis does.
ScoreEvaluation mahalanobis_score(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                                  Derivatives derivatives,
                                  double max_distance = std::numeric_limits<double>::infinity());

/// Σ d1·exp(−d2/2·eᵀC⁻¹e). With `trilinear`, each point scores against the 8 cells whose
/// centres surround it, weighted trilinearly (weights held constant in the derivatives, as
/// Magnusson does).
ScoreEvaluation gaussian_score(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                               const GaussianScoreParams& params, bool trilinear, Derivatives derivatives);

}  // namespace sextant
