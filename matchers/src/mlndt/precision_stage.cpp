// ML-NDT's precision stage (precision_stage.hpp): the grids, and MlndtMatcher::refine, which runs
// them after the pyramid.
#include "sextant/matchers/precision_stage.hpp"

#include <algorithm>
#include <cmath>

#include "mlndt/layer_objective.hpp"
#include "mlndt/run_memo.hpp"
#include "ndt/ndt_score.hpp"
#include "optim/optimizer.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant {

bool PrecisionSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(min_cell == 0.0 || (min_cell >= 0.05 && min_cell <= 100.0)))
    problem = "precision_min_cell must be 0 (off) or lie in [0.05, 100] m";
  else if (!(min_coverage > 0.0 && min_coverage <= 1.0))
    problem = "precision_min_coverage must lie in (0, 1]";
  else if (!(max_eigen_ratio >= 1.0) || !std::isfinite(max_eigen_ratio))
    problem = "precision_max_eigen_ratio must be finite and at least 1";
  else if (!(spacing_cells == 0.0 || (spacing_cells >= 1.0 && spacing_cells <= 1000.0)))
    problem = "precision_spacing_cells must be 0 (off) or lie in [1, 1000]";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

CellStatsSettings PrecisionSettings::cells(const CellStatsSettings& pyramid_cells) const {
  CellStatsSettings c = pyramid_cells;
  c.max_eigen_ratio = max_eigen_ratio;
  return c;
}

std::vector<double> precision_edges(double last_edge, const PrecisionSettings& settings) {
  if (!settings.enabled() || !(last_edge > 0.0)) return {};
  const double finer = std::min(last_edge, std::max(0.5 * last_edge, settings.min_cell));
  if (finer < last_edge) return {finer, last_edge};
  return {last_edge};
}

NdtGrid precision_grid(const PointCloud& reference, const PrecisionFrame& frame, double edge, double shift,
                       const CellStatsSettings& cells) {
  Eigen::Vector3i dims;
  for (int a = 0; a < 3; ++a)  // one cell more when shifted: that grid starts before the box
    dims(a) = static_cast<int>(std::ceil(frame.last_dims(a) * frame.last_edge / edge - 1e-9)) + (shift > 0.0);
  return NdtGrid::build(reference, frame.origin - Eigen::Vector3d::Constant(shift * edge), edge, dims, cells);
}

bool precision_pair_usable(const NdtGrid& aligned, const NdtGrid& shifted, const NdtGrid& last_layer,
                           const PrecisionSettings& settings) {
  const double modelled = static_cast<double>(last_layer.modelled_points());
  return !aligned.empty() && !shifted.empty() && modelled > 0.0 &&
         static_cast<double>(aligned.modelled_points()) >= settings.min_coverage * modelled;
}

RegistrationResult MlndtMatcher::refine(const PointCloud& input, RegistrationResult coarse) {
  const bool usable = coarse.why == Termination::kConverged || coarse.why == Termination::kMaxIterations;
  const std::vector<NdtGrid>& precision = precision_layers();
  if (precision.empty() || !usable) return coarse;
  const int n = settings_.pyramid.layers;
  // Both grids' truncated scores summed (eq. 3.11 over each); the trace labels the stage n + 1.
  const mlndt_detail::OverlappingGridsObjective fine(precision, n + 1, settings_, input, *threads_);
  const RegistrationResult* known = runs_->find(n + 1, coarse.T);
  reused_runs_ += known != nullptr;
  RegistrationResult r = known ? *known : optimize(fine, coarse.T, settings_.optimizer);
  if (!known) runs_->add(n + 1, coarse.T, r);
  coarse.seconds += known ? 0.0 : r.seconds;            // the time spent in this registration
  if (r.why != Termination::kConverged) return coarse;  // the pyramid's pose stands
  // Overlap, fit and the degeneracy check's Hessian stay those of the last layer, at the refined
  // pose: the trust checks (registration_quality.hpp) were measured there. H is the finest grids',
  // whose minimum the pose is (R = H⁻¹, eq. 3.50).
  const ScoreEvaluation at = last_layer_at(input, r.T);
  coarse.before_precision = coarse.T;
  coarse.T = r.T;
  coarse.H = r.H;
  coarse.constraint_hessian = at.hessian;
  coarse.score = at.score;
  coarse.matched_points = at.matched;
  coarse.mean_matched_score = at.matched > 0 ? at.matched_score / static_cast<double>(at.matched) : 0.0;
  coarse.iterations += r.iterations;
  coarse.trace.insert(coarse.trace.end(), r.trace.begin(), r.trace.end());
  return coarse;
}

}  // namespace sextant
