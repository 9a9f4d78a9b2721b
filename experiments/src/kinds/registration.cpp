// `registration` (E1, E2, E4): one run = one (method, scan pair, sweep point, repetition). The
// pair comes from the dataset (consecutive scans i → i + 1, or one pair displaced by a sweep
// offset); the initial guess from odometry, the identity or f · Z_gt; any matcher × sampler.
// Each run records its error per parameter [cm, deg], norms, success, convergence, iterations,
// times, matched points, the kept fraction, the score trace and the transforms themselves (so the
// report rebuilds eval's RegistrationStats exactly).
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "dataset_source.hpp"
#include "kinds.hpp"
#include "registration_report.hpp"
#include "registration_scenes.hpp"
#include "registration_settings.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/match_pair.hpp"

namespace sextant {
namespace {

double point_value(const RunSpec& run, const std::string& axis, double fallback) {
  const auto it = run.point.find(axis);
  return it == run.point.end() ? fallback : std::stod(it->second);
}

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
  }

  void run(const RunSpec& run, RunRow& row) const override {
    const RegistrationMethod& method = methods_.at(run.method_index);
    const bool displaced = params_.pairs == PairSource::kDisplaced;
    const std::size_t a = displaced ? 0 : static_cast<std::size_t>(point_value(run, "pair", 0));
    const std::size_t b = a + 1;

    PointCloud input;
    const PointCloud* reference = nullptr;
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
    DisplacedCase scene;
    if (displaced) {
      // A scene whose input is moved so that the true transform is the run's offset (identity guess).
      scene = scenes_->displace(run);
      reference = scene.reference;
      input = std::move(scene.input);
      truth = scene.truth;
    } else {
      reference = &scans_.at(a);
      input = scans_.at(b);
      truth = relative_pose(dataset_->ground_truth(a), dataset_->ground_truth(b), "ground truth");
    }
    if (!displaced && params_.guess == GuessSource::kOdometry) {
      guess = relative_pose(dataset_->odometry(a), dataset_->odometry(b), "odometry");
    } else if (!displaced && params_.guess == GuessSource::kScaled) {
      guess = to_isometry(Pose6::from_vector(point_value(run, "f", 1.0) * to_pose6(truth).vector()));
    }

    YAML::Node settings =
        method.settings.IsMap() ? YAML::Clone(method.settings) : YAML::Node(YAML::NodeType::Map);
    if (run.point.count("start_layer"))
      settings["start_layer"] = static_cast<int>(point_value(run, "start_layer", 0));
    const auto matcher = make_matcher(method.matcher, settings, "<" + method.name + ">");
    const auto sampler = make_sampler(method.sampler, method.sampler_settings, "<" + method.name + ">");
    Rng rng(run.seed);
    const PairMatch m = match_pair(*matcher, *sampler, *reference, input, guess, rng);

    const RegistrationError error = registration_error(m.result.T, truth, params_.axes);
    const RegistrationError initial = registration_error(guess, truth, params_.axes);
    static const char* const kNames[6] = {"tx", "ty", "tz", "alpha", "beta", "gamma"};
    for (int k = 0; k < 6; ++k)
      row.values[std::string("error_") + kNames[k]] = error.parameters[static_cast<std::size_t>(k)];
    row.values["translation_cm"] = error.translation_cm;
    row.values["rotation_deg"] = error.rotation_deg;
    row.values["initial_translation_cm"] = initial.translation_cm;
    row.values["initial_rotation_deg"] = initial.rotation_deg;
    row.values["success"] =
        thesis_success_criterion(params_.success).succeeded(error, m.result.converged) ? 1.0 : 0.0;
    row.values["converged"] = m.result.converged ? 1.0 : 0.0;
    row.values["termination"] = static_cast<double>(m.result.why);
    row.values["iterations"] = m.result.iterations;
    row.values["seconds_align"] = m.result.seconds;
    row.values["seconds_registration"] = m.result.seconds + m.reference_seconds + m.sampling_seconds;
    row.values["input_points"] = static_cast<double>(m.result.input_points);
    row.values["matched_percent"] = m.result.input_points > 0
                                        ? 100.0 * static_cast<double>(m.result.matched_points) /
                                              static_cast<double>(m.result.input_points)
                                        : NAN;
    row.values["kept_fraction"] = m.kept_fraction;
    if (!displaced) row.values["reference_scan"] = static_cast<double>(a);
    row.series["estimate"] = isometry_to_series(m.result.T);
    row.series["ground_truth"] = isometry_to_series(truth);
    row.series["initial"] = isometry_to_series(guess);
    if (!displaced && dataset_->odometry(a) && dataset_->odometry(b))
      row.series["odometry"] = isometry_to_series(relative(*dataset_->odometry(a), *dataset_->odometry(b)));
    std::vector<double> score, layer;
    for (const auto& t : m.result.trace) {
      score.push_back(t.score);
      layer.push_back(t.layer);
    }
    row.series["score"] = std::move(score);
    row.series["layer"] = std::move(layer);
    if (displaced) record_displaced(scene, input, m.result, row);
  }

 private:
  RegistrationParams params_;
  std::vector<RegistrationMethod> methods_;
  std::unique_ptr<Dataset> dataset_;
  std::map<std::size_t, PointCloud> scans_;
  std::unique_ptr<DisplacedScenes> scenes_;  ///< displaced pairs only

  /// E1's extras: the scene and offset, the pose of every iteration, the clouds of the snapshot run.
  void record_displaced(const DisplacedCase& c, const PointCloud& input, const RegistrationResult& r,
                        RunRow& row) const {
    row.values["scene"] = static_cast<double>(c.scene);
    row.values["cell_edge_m"] = c.cell_edge;
    row.values["offset_m"] = c.offset_m;
    row.values["heading_deg"] = c.heading_deg;
    row.values["yaw_deg"] = c.yaw_deg;
    std::vector<double> xi;  // [tx ty tz α β γ] after each iteration, eq. (3.12)
    for (const auto& t : r.trace) xi.insert(xi.end(), t.xi.data(), t.xi.data() + 6);
    row.series["trace_xi"] = std::move(xi);
    if (!c.snapshot) return;
    const int count = scenes_->settings().snapshot_points;
    row.series["snapshot_reference"] = snapshot_points(*c.reference, count);
    row.series["snapshot_input"] = snapshot_points(input, count);
  }
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
    (void)read_methods(config);
    check_registration_sweep(config, params);
    if (params.pairs == PairSource::kDisplaced)
      check_displaced_sweep(config, read_displaced_settings(config, params));
    check_experiment_dataset(config, "registration");
    check_registration_reference(config, params);
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<RegistrationSession>(config, read_registration_params(config),
                                                 read_methods(config));
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    const RegistrationParams params = read_registration_params(config);
    switch (params.report) {
      case RegistrationLayout::kBasin: return basin_report(config, params, runs, rows);
      case RegistrationLayout::kInitLayer: return init_layer_report(config, params, runs, rows);
      case RegistrationLayout::kAccuracy: break;
    }
    return accuracy_report(config, params, runs, rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_registration_kind() {
  return std::make_unique<RegistrationKind>();
}

}  // namespace sextant
