// ML-NDT's precision stage (precision_stage.hpp): the grids, and MlndtMatcher::refine, which runs
// them after the pyramid.
#include "sextant/matchers/precision_stage.hpp"

#include <algorithm>
#include <cmath>

#include "layer_objective.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant {

bool PrecisionSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(min_cell == 0.0 || (min_cell >= 0.05 && min_cell <= 100.0)))
    problem = "precision_min_cell must be 0 (off) or lie in [0.05, 100] m";
  else if (!(min_coverage > 0.0 && min_coverage <= 1.0))
    problem = "precision_min_coverage must lie in (0, 1]";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

namespace {

/// The grid of edge `edge` over the last layer's box, its origin moved by `shift`·edge along every axis.
NdtGrid precision_grid(const PointCloud& reference, const NdtGrid& last_layer, double edge, double shift,
                       const CellStatsSettings& cells) {
  Eigen::Vector3i dims;
  for (int a = 0; a < 3; ++a)  // one cell more: the shifted grid starts half a cell before the box
    dims(a) = static_cast<int>(std::ceil(last_layer.dims()(a) * last_layer.cell_edge() / edge - 1e-9)) + 1;
  return NdtGrid::build(reference, last_layer.origin() - Eigen::Vector3d::Constant(shift * edge), edge, dims,
                        cells);
}

}  // namespace

std::vector<NdtGrid> build_precision_layers(const PointCloud& reference, const NdtGrid& last_layer,
                                            const PrecisionSettings& settings,
                                            const CellStatsSettings& cells) {
  std::vector<NdtGrid> grids;
  if (!settings.enabled() || last_layer.empty() || last_layer.modelled_points() == 0) return grids;
  const double last = last_layer.cell_edge();
  const double modelled = static_cast<double>(last_layer.modelled_points());
  const auto models_enough = [&](const NdtGrid& g) {
    return !g.empty() && static_cast<double>(g.modelled_points()) >= settings.min_coverage * modelled;
  };
  // Layer n + 1's edge, never below the metric floor; the last layer's own edge when that floor is
  // above it or when the finer cells model too little of the reference.
  const double finer = std::min(last, std::max(0.5 * last, settings.min_cell));
  for (const double edge : {finer, last}) {
    NdtGrid aligned = precision_grid(reference, last_layer, edge, 0.0, cells);
    if (!models_enough(aligned)) continue;
    NdtGrid shifted = precision_grid(reference, last_layer, edge, 0.5, cells);
    if (shifted.empty()) continue;
    grids.push_back(std::move(aligned));
    grids.push_back(std::move(shifted));
    break;
  }
  return grids;
}

RegistrationResult MlndtMatcher::refine(const PointCloud& input, RegistrationResult coarse) const {
  const bool usable = coarse.why == Termination::kConverged || coarse.why == Termination::kMaxIterations;
  if (precision_.empty() || !usable) return coarse;
  const int n = settings_.pyramid.layers;
  // Both grids' truncated scores summed (eq. 3.11 over each); the trace labels the stage n + 1.
  const mlndt_detail::OverlappingGridsObjective fine(precision_, n + 1, settings_, input);
  RegistrationResult r = optimize(fine, coarse.T, settings_.optimizer);
  coarse.seconds += r.seconds;
  if (r.why != Termination::kConverged) return coarse;  // the pyramid's pose stands
  // Overlap and fit stay those of the last layer, at the refined pose: the trust checks
  // (registration_quality.hpp) were measured there. The Hessian is the finest grid's, whose
  // minimum the pose is (R = H⁻¹, eq. 3.50).
  const mlndt_detail::LayerObjective last(layers_, n - 1, n - settings_.truncated_layers, 0, settings_,
                                          input);
  const ScoreEvaluation at = last.evaluate(0, to_pose6(r.T).vector(), Derivatives::kScore);
  coarse.T = r.T;
  coarse.H = r.H;
  coarse.score = at.score;
  coarse.matched_points = at.matched;
  coarse.mean_matched_score = at.matched > 0 ? at.matched_score / static_cast<double>(at.matched) : 0.0;
  coarse.iterations += r.iterations;
  coarse.trace.insert(coarse.trace.end(), r.trace.begin(), r.trace.end());
  return coarse;
}

}  // namespace sextant
