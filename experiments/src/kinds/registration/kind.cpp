// `registration`: one run = one (method, scan pair, sweep point, repetition). The
// pair comes from the dataset (consecutive scans i → i + 1, or one pair displaced by a sweep
// offset); the initial guess from odometry, the identity or f · Z_gt; any matcher × sampler.
// Each run records its error per parameter [cm, deg], norms, success, convergence, iterations,
// times, matched points, the kept fraction, the score trace and the transforms themselves (so the
// report rebuilds eval's RegistrationStats exactly).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "kit/adaptive_start.hpp"
#include "kit/dataset_source.hpp"
#include "kit/row_keys.hpp"
#include "registration/layouts/layouts.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "registration/scenes.hpp"
#include "registration/settings.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

/// The relative pose b ⊖ a from a pose source; throws when the dataset lacks it.
Eigen::Isometry3d relative_pose(const std::optional<Eigen::Isometry3d>& a,
                                const std::optional<Eigen::Isometry3d>& b, const char* what) {
  if (!a || !b) throw std::runtime_error(std::string("the dataset has no ") + what + " for this pair");
  return relative(*a, *b);
}

class RegistrationSession : public KindSession {
 public:
  RegistrationSession(const ExperimentConfig& config, RegistrationParams params,
                      std::vector<RegistrationMethod> methods)
      : params_(std::move(params)),
        methods_(std::move(methods)),
        dataset_(open_experiment_dataset(config, "registration")) {
    if (params_.pairs == PairSource::kDisplaced)
      scenes_ = std::make_unique<DisplacedScenes>(config, params_, *dataset_);
    const std::vector<std::size_t> indices = needed_scans(config, params_);
    for (const std::size_t i : indices) {
      if (i >= dataset_->size())
        throw InputError(config.file, "",
                         "scan " + std::to_string(i) + " is past the dataset's " +
                             std::to_string(dataset_->size()) + " scans");
    }
    std::vector<PointCloud> clouds(indices.size());
    tbb::parallel_for(std::size_t{0}, indices.size(),
                      [&](std::size_t k) { clouds[k] = dataset_->scan(indices[k]); });
    for (std::size_t k = 0; k < indices.size(); ++k) scans_.emplace(indices[k], std::move(clouds[k]));
    // The whole sweep, not the plan: the adaptive run registers every pair of the sweep with the
    // seeds of the fixed-layer runs there, and the plan lacks both when every method is adaptive.
    for (const RunSpec& r : expand_sweep(config)) {
      seeds_.emplace(std::make_pair(r.point, r.repetition), r.seed);
      for (const auto& [axis, label] : r.point) {
        auto& labels = axis_labels_[axis];
        if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
      }
    }
  }

  void run(const RunSpec& run, RunRow& row) const override {
    const RegistrationMethod& method = methods_.at(run.method_index);
    if (method.adaptive) return run_adaptive(run, method, row);
    const bool displaced = params_.pairs == PairSource::kDisplaced;
    const std::size_t a = displaced ? 0 : static_cast<std::size_t>(point_value(run, "pair", 0));
    const int layer =
        run.point.count("start_layer") ? static_cast<int>(point_value(run, "start_layer", 0)) : 0;
    const Outcome o = register_pair(method, run, a, layer, run.seed);
    fill_row(o, displaced, row);
  }

 private:
  /// One registration and what the row records about it.
  struct Outcome {
    std::size_t a = 0, b = 0;
    PairMatch m;
    Eigen::Isometry3d truth, guess;
    DisplacedCase scene;  ///< displaced pairs: the scene, its offset and the moved input
  };

  /// Registers pair a → a + 1 with the guess of `run`'s sweep point, or (displaced) the scene moved
  /// by the run's offset from the identity; `start_layer` > 0 overrides the method's settings.
  Outcome register_pair(const RegistrationMethod& method, const RunSpec& run, std::size_t a, int start_layer,
                        std::uint64_t seed) const {
    Outcome o;
    const PointCloud* reference = nullptr;
    const PointCloud* input = nullptr;
    o.guess = Eigen::Isometry3d::Identity();
    if (params_.pairs == PairSource::kDisplaced) {
      // A scene whose input is moved so that the true transform is the run's offset (identity guess).
      o.scene = scenes_->displace(run);
      reference = o.scene.reference;
      input = &o.scene.input;
      o.truth = o.scene.truth;
    } else {
      o.a = a;
      o.b = a + 1;
      reference = &scans_.at(o.a);
      input = &scans_.at(o.b);
      o.truth = relative_pose(dataset_->ground_truth(o.a), dataset_->ground_truth(o.b), "ground truth");
      if (params_.guess == GuessSource::kOdometry) {
        o.guess = relative_pose(dataset_->odometry(o.a), dataset_->odometry(o.b), "odometry");
      } else if (params_.guess == GuessSource::kScaled) {
        o.guess = to_isometry(Pose6::from_vector(point_value(run, "f", 1.0) * to_pose6(o.truth).vector()));
      }
    }

    MatcherSpec spec = method.matcher;
    if (start_layer > 0) set_start_layer(spec, start_layer);  // checked by check_registration_sweep
    const auto matcher = make_matcher(spec);
    const auto sampler = make_sampler(method.sampler);
    Rng rng(seed);
    o.m = match_pair(*matcher, *sampler, *reference, *input, o.guess, rng);
    return o;
  }

  void fill_row(const Outcome& o, bool displaced, RunRow& row) const {
    const PairMatch& m = o.m;
    const RegistrationError error = registration_error(m.result.T, o.truth, params_.axes);
    const RegistrationError initial = registration_error(o.guess, o.truth, params_.axes);
    static const char* const kNames[6] = {"tx", "ty", "tz", "alpha", "beta", "gamma"};
    for (int k = 0; k < 6; ++k)
      row.values[std::string("error_") + kNames[k]] = error.parameters[static_cast<std::size_t>(k)];
    row.values[keys::kTranslationCm] = error.translation_cm;
    row.values[keys::kRotationDeg] = error.rotation_deg;
    row.values[keys::kInitialTranslationCm] = initial.translation_cm;
    row.values["initial_rotation_deg"] = initial.rotation_deg;
    row.values[keys::kSuccess] =
        thesis_success_criterion(params_.success).succeeded(error, m.result.converged) ? 1.0 : 0.0;
    row.values[keys::kConverged] = m.result.converged ? 1.0 : 0.0;
    row.values["termination"] = static_cast<double>(m.result.why);
    row.values[keys::kIterations] = m.result.iterations;
    row.values[keys::kSecondsAlign] = m.result.seconds;
    row.values[keys::kSecondsSampling] = m.sampling_seconds;
    row.values[keys::kSecondsRegistration] = m.result.seconds + m.reference_seconds + m.sampling_seconds;
    row.values[keys::kInputPoints] = static_cast<double>(m.result.input_points);
    row.values[keys::kMatchedPercent] = m.result.input_points > 0
                                            ? 100.0 * static_cast<double>(m.result.matched_points) /
                                                  static_cast<double>(m.result.input_points)
                                            : NAN;
    row.values[keys::kKeptFraction] = m.kept_fraction;
    if (!displaced) row.values[keys::kReferenceScan] = static_cast<double>(o.a);
    row.series[keys::kEstimate] = isometry_to_series(m.result.T);
    row.series[keys::kGroundTruth] = isometry_to_series(o.truth);
    row.series[keys::kInitial] = isometry_to_series(o.guess);
    if (!displaced && dataset_->odometry(o.a) && dataset_->odometry(o.b))
      row.series[keys::kOdometry] =
          isometry_to_series(relative(*dataset_->odometry(o.a), *dataset_->odometry(o.b)));
    std::vector<double> score, layer, step;
    for (const auto& t : m.result.trace) {
      score.push_back(t.score);
      layer.push_back(t.layer);
      step.push_back(t.step_norm);
    }
    row.series[keys::kScore] = std::move(score);
    row.series[keys::kLayer] = std::move(layer);
    row.series["step_norm"] = std::move(step);
    if (displaced || params_.report->trace_xi) {
      std::vector<double> xi;  // [tx ty tz α β γ] after each iteration, eq. (3.12) (figs 5.3, 5.5, 5.12)
      for (const auto& t : m.result.trace) xi.insert(xi.end(), t.xi.data(), t.xi.data() + 6);
      row.series[keys::kTraceXi] = std::move(xi);
    }
    if (displaced) record_displaced(o.scene, row);
  }

  /// E1's extras: the scene and offset, and the clouds of the snapshot run.
  void record_displaced(const DisplacedCase& c, RunRow& row) const {
    row.values[keys::kScene] = static_cast<double>(c.scene);
    row.values[keys::kCellEdgeM] = c.cell_edge;
    row.values["offset_m"] = c.offset_m;
    row.values["heading_deg"] = c.heading_deg;
    row.values["yaw_deg"] = c.yaw_deg;
    if (!c.snapshot) return;
    const int count = scenes_->settings().snapshot_points;
    row.series[keys::kSnapshotReference] = snapshot_points(*c.reference, count);
    row.series[keys::kSnapshotInput] = snapshot_points(c.input, count);
  }

  /// The adaptive starting layer (kit/adaptive_start.hpp) as one run over every pair of the
  /// sweep, in sweep order, at the run's other axis values. Pair k uses the seed of the fixed-layer
  /// run at (pair k, chosen layer), so it repeats that run exactly. The plan holds only the run at
  /// the first pair and the first start layer (RegistrationKind::planned_runs).
  void run_adaptive(const RunSpec& run, const RegistrationMethod& method, RunRow& row) const {
    const AdaptiveStartSettings& rule = method.adaptive_start;
    std::size_t failures = 0, done = 0;
    std::map<std::string, std::vector<double>> series;
    for (const std::string& pair : axis_labels_.at("pair")) {
      const int layer = adaptive_start_layer(rule, last_layer(method.matcher), failures, done);
      std::map<std::string, std::string> point = run.point;
      point["pair"] = pair;
      if (point.count("start_layer")) point["start_layer"] = layer_label(layer);
      const auto seed = seeds_.find({point, run.repetition});
      const Outcome o = register_pair(method, run, static_cast<std::size_t>(std::stoul(pair)), layer,
                                      seed != seeds_.end() ? seed->second : run.seed + done);
      RunRow one;
      fill_row(o, false, one);
      const Eigen::Isometry3d odometry =
          relative_pose(dataset_->odometry(o.a), dataset_->odometry(o.b), "odometry");
      const bool failed = adaptive_failure(rule, o.m.result.T, odometry);
      failures += failed ? 1 : 0;
      ++done;
      series[keys::kAdaptivePair].push_back(static_cast<double>(o.a));
      series[keys::kAdaptiveStartLayer].push_back(layer);
      series[keys::kAdaptiveRuleFailure].push_back(failed ? 1.0 : 0.0);
      for (const char* v : {keys::kSuccess, keys::kTranslationCm, keys::kRotationDeg,
                            keys::kSecondsRegistration, keys::kIterations})
        series[std::string("adaptive_") + v].push_back(one.value(v));
    }
    for (auto& [name, values] : series) row.series[name] = std::move(values);
    row.values["adaptive_pairs"] = static_cast<double>(done);
    row.values["adaptive_rule_failures"] = static_cast<double>(failures);
  }

  std::string layer_label(int layer) const {
    const auto labels = axis_labels_.find("start_layer");
    if (labels != axis_labels_.end()) {
      for (const auto& l : labels->second) {
        if (std::stod(l) == layer) return l;
      }
    }
    return std::to_string(layer);
  }

  RegistrationParams params_;
  std::vector<RegistrationMethod> methods_;
  std::unique_ptr<Dataset> dataset_;
  std::map<std::size_t, PointCloud> scans_;
  std::unique_ptr<DisplacedScenes> scenes_;  ///< displaced pairs only
  /// Sweep axis → value labels in sweep order (as RunSpec::point spells them), for the adaptive run.
  std::map<std::string, std::vector<std::string>> axis_labels_;
  /// (sweep point, repetition) → run seed, so the adaptive run reuses the fixed-layer runs' seeds.
  std::map<std::pair<std::map<std::string, std::string>, int>, std::uint64_t> seeds_;
};

std::vector<RegistrationMethod> read_methods(const ExperimentConfig& config) {
  std::vector<RegistrationMethod> methods;
  for (const auto& m : config.methods) methods.push_back(read_registration_method(m.node, config.file));
  return methods;
}

class RegistrationKind : public RunKind {
 public:
  std::string name() const override { return "registration"; }

  void validate(const ExperimentConfig& config) const override {
    const RegistrationParams params = read_registration_params(config);
    const std::vector<RegistrationMethod> methods = read_methods(config);
    check_registration_sweep(config, params, methods);
    if (params.pairs == PairSource::kDisplaced)
      check_displaced_sweep(config, read_displaced_settings(config, params));
    check_experiment_dataset(config, "registration");
    params.report->check_reference(config);
    for (std::size_t k = 0; k < methods.size(); ++k) {
      if (!params.report->adaptive_start && methods[k].adaptive)
        throw InputError(
            config.file, at_line(yaml_line(config.methods[k].node)),
            "key 'adaptive_start': the adaptive starting layer is reported by report: init_layer only");
    }
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<RegistrationSession>(config, read_registration_params(config),
                                                 read_methods(config));
  }

  /// An adaptive method's run registers every pair itself (RegistrationSession::run_adaptive), so
  /// its plan holds one run per (other axes' point, repetition): the one at the first pair and the
  /// first start layer. A run at any other pair or start layer would have nothing to do.
  std::vector<bool> planned_runs(const ExperimentConfig& config,
                                 const std::vector<RunSpec>& expansion) const override {
    std::vector<bool> adaptive;
    for (const auto& m : config.methods) adaptive.push_back(declares_adaptive_start(m.node));
    std::map<std::string, std::string> first;  // axis → its first value, as RunSpec::point spells it
    for (const auto& axis : config.sweep) {
      if ((axis.name == "pair" || axis.name == "start_layer") && !axis.values.empty())
        first[axis.name] = point_label(axis.values.front());
    }
    std::vector<bool> planned(expansion.size(), true);
    for (std::size_t k = 0; k < expansion.size(); ++k) {
      if (!adaptive.at(expansion[k].method_index)) continue;
      for (const auto& [axis, label] : first) planned[k] = planned[k] && expansion[k].point.at(axis) == label;
    }
    return planned;
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    const RegistrationParams params = read_registration_params(config);
    return params.report->report(config, params, runs, rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_registration_kind() {
  return std::make_unique<RegistrationKind>();
}

}  // namespace sextant
