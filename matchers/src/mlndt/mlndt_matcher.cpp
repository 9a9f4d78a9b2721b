#include "sextant/matchers/mlndt_matcher.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "mlndt/layer_objective.hpp"
#include "mlndt/mlndt_global_init.hpp"
#include "mlndt/run_memo.hpp"
#include "ndt/ndt_score.hpp"
#include "optim/optimizer.hpp"
#include "sextant/core/checked_settings.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/point_spacing.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/sensor_kind.hpp"

namespace sextant {

using mlndt_detail::LayerObjective;

// The library's defaults are the `default` preset (matchers/yaml.hpp), measured best on the shared
// real pairs and the campus (docs/matcher_defaults.md): LM, n = 4, s = 2, the finest layer's terms
// truncated at 16 and unmatched points charged 16, LM's function tolerance 10⁻⁵. The thesis'
// settings are the `thesis` preset.
MlndtSettings::MlndtSettings() {
  optimizer.solver = SolverKind::kLevenbergMarquardt;
  optimizer.iterations_per_stage = 3;
  optimizer.max_iterations = 50;
  optimizer.epsilon = 1e-4;
  optimizer.function_tolerance = 1e-5;
  // Newton without step control oscillates or diverges in the last layer (issue 11: 160 cm off on
  // the Velodyne pair with GBS); the thesis-faithful plain step stays available as step_control: none.
  optimizer.step_control = StepControl::kTrustRegionLast;
  unmatched_penalty = 16.0;
  max_distance = 16.0;
  pyramid.cells.min_relative_spread = 0.02;  // blobs of repeated points are no surface (ndt_grid.hpp)
}

bool MlndtSettings::valid(std::string* why) const {
  if (!pyramid.valid(why) || !optimizer.valid(why)) return false;
  if (wide_basin.enabled && !wide_basin.valid(why)) return false;
  if (!precision.valid(why)) return false;
  const char* problem = nullptr;
  if (start_layer < 1 || start_layer > pyramid.layers)
    problem = "start_layer must lie in [1, layers]";
  else if (!(unmatched_penalty >= 0.0))
    problem = "unmatched_penalty must be ≥ 0";
  else if (!(max_distance > 0.0))
    problem = "max_distance must be positive (.inf keeps every correspondence)";
  else if (truncated_layers < 0 || truncated_layers > pyramid.layers)
    problem = "truncated_layers must lie in [0, layers]";
  else if (threads < 0)
    problem = "threads must be ≥ 0 (0: all hardware threads)";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

MlndtMatcher::MlndtMatcher(MlndtSettings settings)
    : settings_(checked(std::move(settings), "mlndt")),
      threads_(std::make_unique<ScoreThreads>(settings_.threads)),
      runs_(std::make_unique<mlndt_detail::RunMemo>()) {}

MlndtMatcher::~MlndtMatcher() = default;

void MlndtMatcher::set_reference(const PointCloud& reference) {
  // Splitting and generative processes. The precision grids lie over layer n's box, which only needs
  // the reference's robust box: the pyramid and the first pair of precision grids are built side by
  // side. Where the first pair's edge is layer n + 1's and the layers nest, the aligned grid is
  // layer n + 1 of the pyramid's own split (build_layer_pyramid), and only the shifted one is apart.
  const LayerPyramidSettings& pyramid = settings_.pyramid;
  const Bounds box = robust_bounds(reference, pyramid.bounds_quantile);
  const LayerGeometry last = layer_geometry(box, pyramid.division, pyramid.layers);
  const PrecisionFrame frame{box.min.cast<double>(), last.cell_edge, last.dims};
  PrecisionSettings precision = settings_.precision;
  if (precision.enabled() && precision.spacing_cells > 0.0)
    precision.min_cell =
        std::max(precision.min_cell, precision.spacing_cells * measure_point_spacing(reference).median);
  const std::vector<double> edges = precision_edges(last.cell_edge, precision);
  auto model = std::make_shared<MlndtModel>();
  std::vector<NdtGrid> pair(2);
  const CellStatsSettings precision_cells = settings_.precision.cells(pyramid.cells);
  const auto build_pair = [&](std::size_t task, double edge) {
    pair[task] = precision_grid(reference, frame, edge, task == 0 ? 0.0 : 0.5, precision_cells);
  };
  const bool nested = !edges.empty() && edges.front() == 0.5 * last.cell_edge && pyramid_nests(box, pyramid);
  threads_->for_each(edges.empty() ? 1 : (nested ? 2 : 3), [&](std::size_t task) {
    if (task == 0)
      model->layers =
          build_layer_pyramid(reference, pyramid, box, nested ? &pair[0] : nullptr, &precision_cells);
    else
      build_pair(nested ? 1 : task - 1, edges.front());
  });
  if (nested && pair[0].cell_count() == 0) build_pair(0, edges.front());  // layer n + 1 too large
  for (std::size_t e = 0; e < edges.size() && !model->layers.empty(); ++e) {
    if (e > 0) threads_->for_each(2, [&](std::size_t task) { build_pair(task, edges[e]); });
    if (precision_pair_usable(pair[0], pair[1], model->layers.back(), precision)) {
      model->precision = std::move(pair);
      break;
    }
  }
  model->reference_points = reference.size();
  model_ = std::move(model);
  runs_->clear();
}

namespace {

/// Whether two settings build the same model from one reference (set_reference's inputs).
bool same_model(const MlndtSettings& a, const MlndtSettings& b) {
  const LayerPyramidSettings &p = a.pyramid, &q = b.pyramid;
  return p.division == q.division && p.layers == q.layers && p.bounds_quantile == q.bounds_quantile &&
         p.cells.min_points == q.cells.min_points && p.cells.max_eigen_ratio == q.cells.max_eigen_ratio &&
         p.cells.min_spread == q.cells.min_spread &&
         p.cells.min_relative_spread == q.cells.min_relative_spread &&
         a.precision.min_cell == b.precision.min_cell &&
         a.precision.min_coverage == b.precision.min_coverage &&
         a.precision.max_eigen_ratio == b.precision.max_eigen_ratio &&
         a.precision.spacing_cells == b.precision.spacing_cells;
}

bool same_optimizer(const OptimizerSettings& a, const OptimizerSettings& b) {
  const MoreThuenteSettings &l = a.line_search, &m = b.line_search;
  return a.solver == b.solver && a.iterations_per_stage == b.iterations_per_stage &&
         a.max_iterations == b.max_iterations && a.epsilon == b.epsilon &&
         a.function_tolerance == b.function_tolerance && a.step_control == b.step_control &&
         a.min_matched == b.min_matched && a.dof.active == b.dof.active && l.mu == m.mu && l.eta == m.eta &&
         l.max_step == m.max_step && l.iterations == m.iterations;
}

/// Whether two settings make the same runs on one model: every objective and the optimiser alike
/// (the wide basin and the thread count may differ: they choose starts and share out work).
bool same_runs(const MlndtSettings& a, const MlndtSettings& b) {
  return same_model(a, b) && a.start_layer == b.start_layer && a.unmatched_penalty == b.unmatched_penalty &&
         a.max_distance == b.max_distance && a.truncated_layers == b.truncated_layers &&
         same_optimizer(a.optimizer, b.optimizer);
}

/// Keeps `other`, a solution not chosen, in `best.alternatives` when it converged (without its trace).
void add_alternative(RegistrationResult& best, RegistrationResult other) {
  if (!other.converged) return;
  other.trace.clear();
  other.alternatives.clear();
  best.alternatives.push_back(std::move(other));
}

/// The pyramid's tolerance before a precision stage, in units of ε: 10⁻³ at the default ε, a
/// millimetre or 0.06° (docs/matcher_defaults.md, "Fewer evaluations").
constexpr double kPyramidTolerance = 10.0;

const std::vector<NdtGrid>& no_grids() {
  static const std::vector<NdtGrid> none;
  return none;
}

}  // namespace

bool MlndtMatcher::share_reference(const Matcher& built) {
  const auto* other = dynamic_cast<const MlndtMatcher*>(&built);
  if (other == nullptr || !other->model_ || !same_model(settings_, other->settings_)) return false;
  model_ = other->model_;
  if (same_runs(settings_, other->settings_))
    *runs_ = *other->runs_;
  else
    runs_->clear();
  return true;
}

const std::vector<NdtGrid>& MlndtMatcher::layers() const {
  return model_ ? model_->layers : no_grids();
}

const std::vector<NdtGrid>& MlndtMatcher::precision_layers() const {
  return model_ ? model_->precision : no_grids();
}

ScoreEvaluation MlndtMatcher::last_layer_at(const PointCloud& input, const Eigen::Isometry3d& T) const {
  if (layers().empty() || layers().back().empty()) return {};
  const int n = settings_.pyramid.layers;
  const mlndt_detail::LayerObjective last(layers(), n - 1, n - settings_.truncated_layers, 0, settings_,
                                          input, *threads_);
  return last.evaluate(0, to_pose6(T).vector(), Derivatives::kHessian);
}

double MlndtMatcher::predicted_matched_score() const {
  static const PointCloud kNoInput;  // the prediction depends on the layer's τ alone
  const int n = settings_.pyramid.layers;
  return mlndt_detail::LayerObjective(layers(), n - 1, n - settings_.truncated_layers, 0, settings_, kNoInput,
                                      *threads_)
      .predicted_matched_score();
}

RegistrationResult MlndtMatcher::align(const PointCloud& input, const Eigen::Isometry3d& initial) {
  const std::vector<NdtGrid>& layers = this->layers();
  if (layers.empty() || layers.back().empty())
    return not_started(layers.empty() ? Termination::kEmptyInput
                                      : empty_model_reason(model_->reference_points, layers.back()),
                       input.size(), initial);
  const auto start = std::chrono::steady_clock::now();
  // The runs, each an objective from a start: the pyramid from the start layer at the guess; with
  // refine_first the last layer alone there too (§5.1.1.3: a good guess starts at the last layer);
  // with the wide basin its hypotheses, each from the layer they were scored at: a hypothesis lies
  // within half a grid step of its pose, and the coarser layers would only pull it back towards the
  // guess (on sparse keyframes their cells hold single lidar rings, which coincide at zero motion).
  const LayerObjective pyramid(layers, settings_, input, *threads_);
  MlndtSettings last_layer = settings_, from_scoring = settings_;
  last_layer.start_layer = settings_.pyramid.layers;
  from_scoring.start_layer =
      std::max(settings_.start_layer,
               static_cast<int>(wide_basin_layer(layers, 2.0 * settings_.wide_basin.translation_step)) + 1);
  const LayerObjective last_only(layers, last_layer, input, *threads_);
  const LayerObjective hypothesis(layers, from_scoring, input, *threads_);
  std::vector<std::pair<const LayerObjective*, Eigen::Isometry3d>> runs{{&pyramid, initial}};
  if (settings_.refine_first && settings_.start_layer < settings_.pyramid.layers)
    runs.emplace_back(&last_only, initial);
  if (settings_.wide_basin.enabled) {
    const std::vector<Eigen::Isometry3d> starts =
        wide_basin_starts(layers, input, initial, settings_.wide_basin, *threads_);
    for (std::size_t k = 1; k < starts.size(); ++k)
      runs.emplace_back(&hypothesis, starts[k]);  // 0: the guess
  }
  // With a precision stage after them, the runs only have to end in its basin (cells of half the
  // last layer's edge, or more): they stop at kPyramidTolerance × ε, and the precision stage goes on
  // to ε. Where it cannot run or does not converge, the run's pose stands.
  OptimizerSettings optimizer = settings_.optimizer;
  if (!precision_layers().empty()) optimizer.epsilon *= kPyramidTolerance;
  // A run this input already made on this model (run_memo.hpp) is not made again.
  runs_->keep_only(model_, input);
  reused_runs_ = 0;
  std::vector<RegistrationResult> results;
  std::vector<bool> passes;
  const QualitySettings checks;
  const auto make_runs = [&](std::size_t from) {
    std::vector<const RegistrationResult*> known(runs.size() - from);
    for (std::size_t k = from; k < runs.size(); ++k)
      known[k - from] = runs_->find(runs[k].first->stage_label(0), runs[k].second);
    reused_runs_ += static_cast<int>(known.size() - std::count(known.begin(), known.end(), nullptr));
    results.resize(runs.size());
    threads_->for_each(known.size(), [&](std::size_t i) {
      const std::size_t k = from + i;
      results[k] = known[i] ? *known[i] : optimize(*runs[k].first, runs[k].second, optimizer);
    });
    for (std::size_t k = from; k < runs.size(); ++k) {
      if (!known[k - from]) runs_->add(runs[k].first->stage_label(0), runs[k].second, results[k]);
      passes.push_back(assess_registration(results[k], input, checks).trusted());
    }
  };
  make_runs(0);
  // Tilted starts (mlndt_global_init.hpp) only when no run passes the trust checks, and for a narrow
  // view: a view all around brings its own tilt back (sensor_kind.hpp).
  if (settings_.wide_basin.enabled && std::none_of(passes.begin(), passes.end(), [](bool p) { return p; }) &&
      detect_sensor(input).kind == SensorKind::solid_state) {
    const std::size_t level = runs.size();
    for (const Eigen::Isometry3d& T :
         wide_basin_tilted_starts(layers, input, initial, settings_.wide_basin, *threads_))
      runs.emplace_back(&hypothesis, T);
    if (runs.size() > level) make_runs(level);
  }
  // A run that passes the trust checks (registration_quality.hpp, default thresholds) wins over one
  // that does not; among equals the lowest final score (same input, same last layer: the scores
  // compare directly), the first of equals. The score alone let the coarse layers' pose win from the
  // reference pose of sparse keyframes (MulRan 164→165: 8 m back to zero motion, fit 1.41, where the
  // unmatched penalty rewards a pose whose lidar rings coincide with the reference's) over the last
  // layer's, which stayed and passes. The others stay as alternatives (ambiguity).
  std::size_t chosen = 0;
  bool have = false;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const RegistrationResult& r = results[k];
    const bool usable = r.why == Termination::kConverged || r.why == Termination::kMaxIterations;
    const bool better = passes[k] != passes[chosen] ? passes[k] : r.score < results[chosen].score;
    if (!have || (usable && better)) {
      chosen = k;
      have = usable;
    }
  }
  RegistrationResult best = std::move(results[chosen]);
  for (std::size_t k = 0; k < results.size(); ++k)
    if (k != chosen) add_alternative(best, std::move(results[k]));
  best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return refine(input, std::move(best));
}

}  // namespace sextant
