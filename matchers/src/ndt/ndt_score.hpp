#pragma once
// The two NDT objectives over a cell grid, with analytic derivatives in ξ = [tx ty tz α β γ]
// (eq. 3.12, R = Rx(α)·Ry(β)·Rz(γ), eq. 3.8). Both are minimised:
//   Mahalanobis (ML-NDT): f = Σ eᵀC⁻¹e, e = R·x + t − μ                         eqs. (3.10)–(3.18)
//   Gaussian (P2D-NDT):   f = Σ d1·exp(−d2/2 · eᵀC⁻¹e)   (Magnusson's score; d1 < 0) eq. (3.6)
// Points whose cell has no Gaussian are skipped (matched counts the others).
//
// Threads: the input is summed in fixed blocks of kScoreBlockPoints consecutive points, each
// block from zero, and the block sums are added in block order on the calling thread. Neither
// the blocks nor the order of any addition depend on the thread count, so every thread count
// (1 included, which runs the same blocks one after another without TBB) gives bit-identical
// results.
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {

/// Points per accumulation block (see the header comment). Fixed: a block size that followed
/// the thread count would change the rounding of the sums with it.
inline constexpr std::size_t kScoreBlockPoints = 2048;

/// Where the score kernels run. 1 (the default): on the calling thread, without TBB. More: in a
/// TBB task arena of that many threads (at most what TBB allows: the hardware, or a
/// tbb::global_control limit), created once here and reused by every evaluation given this
/// object: keep one per registration, not per evaluation (on the 2-core development machine a
/// fresh arena per call made a 2-thread, 20,000-point evaluation take ≈ 345 µs instead of
/// ≈ 270 µs). The thread count never changes the results. Several threads may share one object.
class ScoreThreads {
 public:
  /// `threads` ≤ 0: all the threads TBB allows.
  explicit ScoreThreads(int threads = 1);
  ~ScoreThreads();
  ScoreThreads(const ScoreThreads&) = delete;
  ScoreThreads& operator=(const ScoreThreads&) = delete;

  /// Threads actually used (1: the calling thread only).
  int concurrency() const { return concurrency_; }
  /// body(i) for every i in [0, count), spread over the threads in any order (one task per i).
  void for_each(std::size_t count, const std::function<void(std::size_t)>& body) const;

 private:
  struct Arena;
  int concurrency_ = 1;
  std::unique_ptr<Arena> arena_;
};

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
  /// The matched points' share of `score` (an objective may add penalties for the others)
  double matched_score = 0.0;
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
                                  double max_distance = std::numeric_limits<double>::infinity(),
                                  const ScoreThreads& threads = ScoreThreads());

/// Σ d1·exp(−d2/2·eᵀC⁻¹e). With `trilinear`, each point scores against the 8 cells whose
/// centres surround it, weighted trilinearly (weights held constant in the derivatives, as
/// Magnusson does).
ScoreEvaluation gaussian_score(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                               const GaussianScoreParams& params, bool trilinear, Derivatives derivatives,
                               const ScoreThreads& threads = ScoreThreads());

}  // namespace sextant
