#include "sextant/matchers/ndt_matcher.hpp"

#include <cmath>

#include "ndt/ndt_score.hpp"
#include "optim/optimizer.hpp"
#include "sextant/core/checked_settings.hpp"

namespace sextant {

namespace {

class GaussianObjective final : public StagedObjective {
 public:
  GaussianObjective(const NdtGrid& grid, const GaussianScoreParams& params, bool trilinear, int threads,
                    const PointCloud& input)
      : grid_(grid), params_(params), trilinear_(trilinear), threads_(threads), input_(input) {}
  int stages() const override { return 1; }
  int stage_label(int /*stage*/) const override { return 0; }
  ScoreEvaluation evaluate(int /*stage*/, const Vector6d& xi, Derivatives d) const override {
    return gaussian_score(grid_, input_, xi, params_, trilinear_, d, threads_);  // eq. (3.6)
  }
  const NdtGrid* mahalanobis_grid(int /*stage*/) const override { return nullptr; }
  const PointCloud& input() const override { return input_; }

 private:
  const NdtGrid& grid_;
  const GaussianScoreParams& params_;
  bool trilinear_;
  ScoreThreads threads_;  ///< one TBB arena for all evaluations of the registration
  const PointCloud& input_;
};

}  // namespace

NdtSettings::NdtSettings() {
  optimizer.iterations_per_stage = 1;
  optimizer.max_iterations = 35;
  optimizer.step_control = StepControl::kLineSearch;
}

bool NdtSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(cell_size >= 0.0) || !std::isfinite(cell_size))
    problem = "cell_size must be ≥ 0 metres (0: from the volume)";
  else if (cell_size > kMaxNdtCellSize)
    problem = "cell_size must be ≤ 1000 m: a cell that holds a whole scan leaves one Gaussian to match";
  else if (volume_divisions < 1)
    problem = "volume_divisions must be at least 1";
  else if (!(outlier_ratio > 0.0 && outlier_ratio < 1.0))
    problem = "outlier_ratio must lie in (0, 1)";
  else if (optimizer.solver == SolverKind::kCeres)
    problem = "ndt supports the solvers newton and lm";
  else if (threads < 0)
    problem = "threads must be ≥ 0 (0: all hardware threads)";
  if (problem && why) *why = problem;
  if (problem) return false;
  return cells.valid(why) && optimizer.valid(why);
}

NdtMatcher::NdtMatcher(NdtSettings settings) : settings_(checked(std::move(settings), "ndt")) {}

void NdtMatcher::set_reference(const PointCloud& reference) {
  double edge = settings_.cell_size;
  if (edge <= 0.0) edge = layer_geometry(reference.bounds(), settings_.volume_divisions, 1).cell_edge;
  grid_ = NdtGrid::build_over_bounds(reference, edge, settings_.cells);
  reference_points_ = reference.size();
  cell_edge_ = edge;
}

RegistrationResult NdtMatcher::align(const PointCloud& input, const Eigen::Isometry3d& initial) {
  if (grid_.empty()) return not_started(empty_model_reason(reference_points_, grid_), input.size(), initial);
  const GaussianScoreParams params =
      GaussianScoreParams::from_outlier_ratio(settings_.outlier_ratio, cell_edge_);
  const GaussianObjective objective(grid_, params, settings_.trilinear, settings_.threads, input);
  return optimize(objective, initial, settings_.optimizer);
}

}  // namespace sextant
