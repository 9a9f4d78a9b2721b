#pragma once
// ML-NDT's layers as the optimiser's stages (mlndt_matcher.cpp), shared with the precision stage
// (precision_stage.cpp), whose finer layers run through the same objective.
#include <cmath>
#include <limits>
#include <vector>

#include "ndt/ndt_score.hpp"
#include "optim/optimizer.hpp"
#include "sextant/core/chi_square.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant::mlndt_detail {

/// Grids first..end of `grids` as stages; the terms of grids from `first_truncated` on are
/// truncated at τ = max_distance; stage k is labelled label_offset + first + k + 1 in traces. Every
/// evaluation runs on `threads` (the registration's, MlndtMatcher's).
class LayerObjective final : public StagedObjective {
 public:
  LayerObjective(const std::vector<NdtGrid>& grids, int first, int first_truncated, int label_offset,
                 const MlndtSettings& settings, const PointCloud& input, const ScoreThreads& threads)
      : layers_(grids),
        first_(first),
        label_offset_(label_offset),
        penalty_(settings.unmatched_penalty),
        max_distance_(settings.max_distance),
        first_truncated_(first_truncated),
        threads_(threads),
        input_(input) {}
  /// The pyramid of `settings` from its start layer.
  LayerObjective(const std::vector<NdtGrid>& layers, const MlndtSettings& settings, const PointCloud& input,
                 const ScoreThreads& threads)
      : LayerObjective(layers, settings.start_layer - 1, settings.pyramid.layers - settings.truncated_layers,
                       0, settings, input, threads) {}
  int stages() const override { return static_cast<int>(layers_.size()) - first_; }
  int stage_label(int stage) const override { return label_offset_ + first_ + stage + 1; }
  ScoreEvaluation evaluate(int stage, const Vector6d& xi, Derivatives d) const override {
    // eqs. (3.11), (3.17), (3.18) with each term truncated at max_distance: min(eᵀC⁻¹e, τ)
    const double tau = max_distance(stage);
    ScoreEvaluation e = mahalanobis_score(grid(stage), input_, xi, d, tau, threads_);
    e.matched_score = e.score;
    const std::size_t unmatched = input_.size() - e.matched - e.rejected;
    e.score += penalty_ * static_cast<double>(unmatched);
    if (e.rejected > 0) e.score += tau * static_cast<double>(e.rejected);  // never ∞·0
    return e;
  }
  double unmatched_penalty() const override { return penalty_; }
  double max_distance(int stage) const override {
    return first_ + stage >= first_truncated_ ? max_distance_ : std::numeric_limits<double>::infinity();
  }
  const NdtGrid* mahalanobis_grid(int stage) const override { return &grid(stage); }
  const PointCloud& input() const override { return input_; }
  /// E[X | X ≤ τ] for X = eᵀC⁻¹e ~ χ²₃: 3·F₅(τ)/F₃(τ) (points beyond τ are not matched); 2.98 at
  /// τ = 16, 3 for the plain sum
  double predicted_matched_score() const override {
    const double tau = max_distance(stages() - 1);
    if (!std::isfinite(tau)) return 3.0;
    return 3.0 * chi_square_cdf(tau, 5.0) / chi_square_cdf(tau, 3.0);
  }

 private:
  const NdtGrid& grid(int stage) const { return layers_[static_cast<std::size_t>(first_ + stage)]; }
  const std::vector<NdtGrid>& layers_;
  int first_;
  int label_offset_;
  double penalty_;
  double max_distance_;
  int first_truncated_;  ///< index of the first grid with truncated terms
  const ScoreThreads& threads_;
  const PointCloud& input_;
};

/// The precision stage's one stage (precision_stage.hpp): the sum of the truncated scores of eq.
/// (3.11) over overlapping grids of one edge, shifted against each other by half a cell (Biber and
/// Straßer's overlapping grids, reduced to the diagonal shift): no cell boundary of one grid is one
/// of the other, so a point that crosses a boundary changes only half of its terms. Derivatives sum
/// with the scores (eqs. 3.17, 3.18); matched and rejected are means over the grids. The grids are
/// evaluated side by side on `threads` and summed in grid order (the same sums for any thread count).
/// Ceres' residuals are per grid: with solver ceres the stage refines on the first (aligned) grid only.
class OverlappingGridsObjective final : public StagedObjective {
 public:
  OverlappingGridsObjective(const std::vector<NdtGrid>& grids, int label, const MlndtSettings& settings,
                            const PointCloud& input, const ScoreThreads& threads)
      : each_(grids, 0, 0, 0, settings, input, threads),
        grids_(static_cast<int>(grids.size())),
        label_(label),
        threads_(threads) {}
  int stages() const override { return 1; }
  int stage_label(int /*stage*/) const override { return label_; }
  ScoreEvaluation evaluate(int /*stage*/, const Vector6d& xi, Derivatives d) const override {
    std::vector<ScoreEvaluation> each(static_cast<std::size_t>(grids_));
    threads_.for_each(each.size(),
                      [&](std::size_t g) { each[g] = each_.evaluate(static_cast<int>(g), xi, d); });
    ScoreEvaluation sum;
    for (const ScoreEvaluation& e : each) {
      sum.score += e.score;
      sum.gradient += e.gradient;
      sum.hessian += e.hessian;
      sum.gauss_newton += e.gauss_newton;
      sum.matched += e.matched;
      sum.rejected += e.rejected;
      sum.matched_score += e.matched_score;
    }
    const auto n = static_cast<std::size_t>(grids_);
    sum.matched /= n;
    sum.rejected /= n;
    sum.matched_score /= static_cast<double>(grids_);
    return sum;
  }
  double unmatched_penalty() const override { return each_.unmatched_penalty(); }
  double max_distance(int /*stage*/) const override { return each_.max_distance(0); }
  const NdtGrid* mahalanobis_grid(int /*stage*/) const override { return each_.mahalanobis_grid(0); }
  const PointCloud& input() const override { return each_.input(); }
  double predicted_matched_score() const override { return each_.predicted_matched_score(); }

 private:
  LayerObjective each_;  ///< grid g is its stage g, every one truncated
  int grids_;
  int label_;
  const ScoreThreads& threads_;
};

}  // namespace sextant::mlndt_detail
