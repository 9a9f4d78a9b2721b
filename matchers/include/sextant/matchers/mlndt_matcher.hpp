#pragma once
// Multi-Layered NDT (§3.2, Table 3.1): a layer pyramid over the reference's bounding box,
// Mahalanobis score (eq. 3.11), start layer s, three iterations per layer, then the last layer
// until ‖Δξ‖ < ε. YAML keys: division, layers, start_layer, solver (newton | lm | ceres),
// iterations_per_layer, max_iterations, unmatched_penalty, max_distance, truncated_layers, epsilon,
// function_tolerance (lm: optimizer.hpp), step_control (newton: trust_region_last by default; none =
// eq. 3.16 as printed), min_points, max_eigen_ratio, min_spread, bounds_quantile, refine_first, dof,
// threads, precision_min_cell, precision_min_coverage (the precision stage of precision_stage.hpp),
// wide_basin (a map, absent = off: the global initialisation of mlndt_global_init.hpp; `wide_basin: {}`
// uses its defaults).
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/optimizer_settings.hpp"
#include "sextant/matchers/precision_stage.hpp"
#include "sextant/matchers/wide_basin_settings.hpp"

namespace sextant {

struct MlndtSettings {
  LayerPyramidSettings pyramid;  ///< q = 8, n = 4, cells with > 4 points, eigenvalue ratio 100
  int start_layer = 2;           ///< s: the first layer used [1, n] (§5: 2 without initial guess)
  /// Score charged for an input point outside every Gaussian, so that a step cannot lower the
  /// score by pushing points out of the cells (the thesis leaves this open; the `thesis` preset
  /// charges 50) [Mahalanobis units]
  double unmatched_penalty = 16.0;
  /// τ: each term of eq. (3.11) becomes min(eᵀC⁻¹e, τ) (a truncated quadratic: outliers from
  /// moving objects and non-overlap add a constant, no gradient); .inf keeps the thesis' plain
  /// sum (the `thesis` preset). 16 ≈ the 99.9 % quantile of χ² with 3 DOF [Mahalanobis units]
  double max_distance = 16.0;
  /// The truncation applies in the finest `truncated_layers` layers only: coarse layers keep
  /// the plain sum, whose long tails give ML-NDT its capture range [count, 0..n]
  int truncated_layers = 1;
  /// Threads of one registration (the model's grids, refine_first's runs, the wide basin, each score
  /// evaluation; a Ceres solve stays serial): 1 the calling thread, 0 all TBB allows (`sextant --jobs`).
  /// Bit-identical for every value (same choices, fixed summation order: ndt_score.hpp) [count, ≥ 0]
  int threads = 1;
  OptimizerSettings optimizer;  ///< solver (LM), iterations per layer (3), cap (50), ε, DOF mask
  /// Off by default: hypotheses over yaw × x/y scored at a coarse layer, the best refined
  WideBasinSettings wide_basin;
  /// Besides the pyramid from start_layer, the last layer alone runs from the initial pose (§5.1.1.3);
  /// a run the trust checks pass wins, else the lower final score, and the other is an alternative.
  /// Keeps a good guess, for one run more; off in `thesis` (docs/matcher_defaults.md, "A good guess is kept")
  bool refine_first = true;
  /// Finer grids after the pyramid's pose, from that pose only (precision_stage.hpp); off
  /// (min_cell 0) in the `thesis` preset
  PrecisionSettings precision;
  MlndtSettings();
  bool valid(std::string* why) const;
};

/// The reference model of set_reference: the layer pyramid and the precision stage's grids.
struct MlndtModel {
  std::vector<NdtGrid> layers;
  std::vector<NdtGrid> precision;  ///< coarse to fine; empty: no stage
  std::size_t reference_points = 0;
};

class ScoreThreads;      // matchers/src/ndt/ndt_score.hpp
struct ScoreEvaluation;  // matchers/src/ndt/ndt_score.hpp
namespace mlndt_detail {
class RunMemo;
}

class MlndtMatcher final : public Matcher {
 public:
  explicit MlndtMatcher(MlndtSettings settings = {});
  ~MlndtMatcher() override;
  std::string name() const override { return "mlndt"; }
  void set_reference(const PointCloud& reference) override;
  /// Takes `built`'s model when it is an MlndtMatcher whose settings build the same one (pyramid,
  /// cells and precision stage; the optimiser and the wide basin may differ): odometry's wide-basin
  /// recovery registers against the model its first try built. When the settings also make the same
  /// runs (all but the wide basin equal), it takes the runs `built` made on that model too: a run
  /// repeated on the same input is not computed again (run_memo.hpp).
  bool share_reference(const Matcher& built) override;
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override;

  const std::vector<NdtGrid>& layers() const;
  /// The precision stage's grids for the current reference, coarse to fine (empty: no stage).
  const std::vector<NdtGrid>& precision_layers() const;
  /// The last layer's view of `input` at the pose `T` (reference ← input): its truncated score with
  /// matched points, matched terms and Hessian, as the trust checks read every result of this
  /// matcher (registration_quality.hpp), whichever matcher found `T` (judged_matcher.hpp). Nothing
  /// matched before set_reference or without Gaussians.
  ScoreEvaluation last_layer_at(const PointCloud& input, const Eigen::Isometry3d& T) const;
  /// What a matched term of the last layer averages at a right pose, E[χ²₃ | ≤ τ]: the fit's
  /// denominator (LayerObjective::predicted_matched_score).
  double predicted_matched_score() const;
  const MlndtSettings& settings() const { return settings_; }
  /// How many of the last align's runs (the optimisations from one start, the precision stage's
  /// included) were taken from an earlier registration of the same input on the same model [count]
  int reused_runs() const { return reused_runs_; }

 private:
  /// The precision stage from `coarse`'s pose (precision_stage.cpp); `coarse` as it is when there is
  /// no stage, coarse did not end usably, or the stage does not converge.
  RegistrationResult refine(const PointCloud& input, RegistrationResult coarse);

  MlndtSettings settings_;
  std::unique_ptr<ScoreThreads> threads_;    ///< settings_.threads, for every registration of this matcher
  std::shared_ptr<const MlndtModel> model_;  ///< null before set_reference
  std::unique_ptr<mlndt_detail::RunMemo> runs_;  ///< this input's runs on model_
  int reused_runs_ = 0;
};

}  // namespace sextant
