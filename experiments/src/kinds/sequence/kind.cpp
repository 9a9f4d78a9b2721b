// `sequence`: one run = one method over consecutive scans first_scan … first_scan +
// scans − 1. Each registration i−1 ← i starts from the odometry increment (run_odometry of
// odometry.hpp, the library behind `sextant odometry`); the relative poses are chained from the true first
// pose (dead reckoning, §5.1.3, fig 5.15) or fused with the odometry by Table 3.3's linear KF (§3.4.2,
// §5.1.3.2). The row holds the trajectories (truth, odometry, estimate, and for the KF the matcher alone and
// the position covariance) and per-step status.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "kit/dataset_source.hpp"
#include "kit/row_codec.hpp"
#include "kit/row_keys.hpp"
#include "sequence/layouts/layouts.hpp"
#include "sequence/report.hpp"
#include "sequence/row_keys.hpp"
#include "sequence/settings.hpp"
#include "sextant/core/chi_square.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant/synth/odometry.hpp"

namespace sextant {
namespace {

constexpr char kKind[] = "sequence";

/// The session's scans, loaded once in prepare(), through the Dataset interface: every run reads
/// them from memory instead of generating (campus) or reading (folder) them again.
class PreloadedDataset : public Dataset {
 public:
  PreloadedDataset(const Dataset& inner, std::size_t first, const std::vector<PointCloud>& scans)
      : inner_(inner), first_(first), scans_(scans) {}
  const DatasetMetadata& metadata() const override { return inner_.metadata(); }
  PointCloud scan(std::size_t i, ScanLoadReport* report) const override {
    if (i >= first_ && i - first_ < scans_.size()) return scans_[i - first_];
    return inner_.scan(i, report);
  }
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override { return inner_.odometry(i); }
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override {
    return inner_.ground_truth(i);
  }
  std::optional<double> stamp(std::size_t i) const override { return inner_.stamp(i); }

 private:
  const Dataset& inner_;
  std::size_t first_;
  const std::vector<PointCloud>& scans_;
};

/// The largest |mean| / standard deviation over the axes of the registrations' translation errors (in
/// each previous scan's frame): a bias b·σ per step adds up to n·b·σ over n steps where independent errors
/// add up to √n·σ. NaN with fewer than two errors.
double largest_bias(const std::vector<Eigen::Vector3d>& errors) {
  if (errors.size() < 2) return kNaN;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), square = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& e : errors) mean += e;
  mean /= static_cast<double>(errors.size());
  for (const Eigen::Vector3d& e : errors) square += (e - mean).cwiseAbs2();
  const Eigen::Vector3d sd = (square / static_cast<double>(errors.size() - 1)).cwiseSqrt();
  return (mean.cwiseAbs().array() / sd.array()).maxCoeff();
}

/// Table 3.3 takes R = H⁻¹ of a world-frame pose; the matcher's H is over ξ of the relative pose in
/// the previous scan's frame. t_world = t_prev + R_prev·t, and the angles add to first order, so
/// H_world = A·H·Aᵀ with A = diag(R_prev, I) (A orthogonal), scaled by 1 / measurement_noise_scale.
Matrix6d world_hessian(const Matrix6d& H, const Eigen::Isometry3d& previous, double scale) {
  Matrix6d A = Matrix6d::Identity();
  A.topLeftCorner<3, 3>() = previous.linear();
  return (A * H * A.transpose()) / scale;
}

class SequenceSession : public KindSession {
 public:
  SequenceSession(const ExperimentConfig& config, SequenceParams params,
                  std::vector<RegistrationMethod> methods)
      : params_(std::move(params)),
        methods_(std::move(methods)),
        dataset_(open_experiment_dataset(config, kKind)) {
    const std::size_t end = params_.first_scan + params_.scans;
    if (end > dataset_->size())
      throw InputError(config.file, "",
                       "key 'params': scans " + std::to_string(params_.first_scan) + "–" +
                           std::to_string(end - 1) + " go past the dataset's " +
                           std::to_string(dataset_->size()) + " scans");
    for (std::size_t k = 0; k < params_.scans; ++k) {
      const auto truth = dataset_->ground_truth(params_.first_scan + k);
      if (!truth)
        throw InputError(config.file, "", "the dataset has no ground truth for scan " + std::to_string(k));
      truth_.push_back(*truth);
      if (params_.odometry == SequenceOdometry::kDataset) {
        const auto odometry = dataset_->odometry(params_.first_scan + k);
        if (!odometry)
          throw InputError(config.file, "", "the dataset has no odometry for scan " + std::to_string(k));
        odometry_.push_back(*odometry);
      }
    }
    if (const auto* campus = dynamic_cast<const synth::CampusDataset*>(dataset_.get()))
      odometry_model_ = campus->campus().settings.odometry;
    else if (config.dataset.simulates_odometry())
      odometry_model_ = simulated_odometry_settings(config);  // a real sequence's reference, corrupted
    scans_.resize(params_.scans);
    tbb::parallel_for(std::size_t{0}, params_.scans,
                      [&](std::size_t k) { scans_[k] = dataset_->scan(params_.first_scan + k); });
  }

  void run(const RunSpec& run, RunRow& row) const override {
    const RegistrationMethod& method = methods_.at(run.method_index);
    Rng master(run.seed);
    Rng odometry_rng = master.split();
    const PoseList odometry = params_.odometry == SequenceOdometry::kDataset
                                  ? odometry_
                                  : synth::simulate_odometry(truth_, odometry_model_, odometry_rng);

    // Dead reckoning by the matcher alone, from the true first pose (fig 5.15): each registration
    // starts from the odometry increment, so run_odometry runs them in parallel.
    OdometrySettings chain_settings;
    chain_settings.registration = {matcher_choice(method.matcher), sampler_factory(method.sampler)};
    chain_settings.guess = OdometryGuess::odometry;
    chain_settings.map = OdometryMap::scan;
    chain_settings.odometry = odometry;
    chain_settings.initial_pose = truth_.front();
    chain_settings.recover = false;      // §5.1.3's dead reckoning chains every registration as it is
    chain_settings.common_view = false;  // and registers the whole scans
    chain_settings.seeds.resize(params_.scans);  // the sampler seeds this kind has always used
    for (auto& seed : chain_settings.seeds) seed = master.bits();
    const PreloadedDataset scans(*dataset_, params_.first_scan, scans_);
    const OdometryResult chain = run_odometry(scans, chain_settings, params_.first_scan, params_.scans);
    const std::vector<OdometryStep>& steps = chain.steps;  // steps[k − 1]: scan k in scan k − 1's frame
    const PoseList& chained = chain.poses;
    PoseList estimate = chained;
    std::vector<double> alarms(params_.scans, 0.0), covariance;
    if (params_.filter == SequenceFilter::kKf) {
      estimate = run_kf(steps, odometry, params_.kf, params_.measurement_noise_scale, alarms, covariance);
      consistency(steps, odometry, row);
    }

    row.series[keys::kGroundTruth] = poses_to_series(truth_);
    row.series[keys::kOdometry] = poses_to_series(odometry);
    row.series[keys::kEstimate] = poses_to_series(estimate);
    if (params_.filter == SequenceFilter::kKf) {
      row.series[keys::kMatcher] = poses_to_series(chained);
      row.series[keys::kCovarianceXyz] = std::move(covariance);
    }
    std::vector<double> converged, iterations, seconds;
    double total_seconds = 0, failures = 0;
    for (const OdometryStep& step : steps) {
      converged.push_back(step.converged ? 1.0 : 0.0);
      iterations.push_back(step.iterations);
      seconds.push_back(step.seconds);
      total_seconds += step.seconds;
      failures += step.converged ? 0 : 1;
    }
    row.series[keys::kConverged] = std::move(converged);
    row.series[keys::kIterations] = std::move(iterations);
    row.series[keys::kSeconds] = std::move(seconds);
    const std::vector<double> odometry_xy = horizontal_errors(odometry, truth_);
    const std::vector<double> estimate_xy = horizontal_errors(estimate, truth_);
    row.values[keys::kEndXyOdometry] = odometry_xy.back();
    row.values[keys::kEndXyEstimate] = estimate_xy.back();
    row.values["end_3d_estimate"] = position_errors(estimate, truth_).back();
    row.values["end_xy_matcher"] = horizontal_errors(chained, truth_).back();
    row.values["max_xy_odometry"] = *std::max_element(odometry_xy.begin(), odometry_xy.end());
    row.values["max_xy_estimate"] = *std::max_element(estimate_xy.begin(), estimate_xy.end());
    row.values[keys::kMeanXyOdometry] = mean_of(odometry_xy);
    row.values[keys::kMeanXyEstimate] = mean_of(estimate_xy);
    row.values["mean_xy_matcher"] = mean_of(horizontal_errors(chained, truth_));
    row.values["path_length"] = path_distances(truth_).back();
    row.values[keys::kNotConverged] = failures;
    row.values["seconds_registration_mean"] = total_seconds / static_cast<double>(params_.scans - 1);
    if (params_.filter == SequenceFilter::kKf) {
      double count = 0;
      for (const double a : alarms) count += a;
      row.values[keys::kAlarms] = count;
      row.series["alarm"] = std::vector<double>(alarms.begin() + 1, alarms.end());
    }
  }

 private:
  /// Table 3.3 (or the relative fusion, `kf.measurement`) over the sequence with R = noise_scale · H⁻¹;
  /// alarms[k] = 1 when step k kept the odometry prediction; covariance: the position blocks, row-major.
  PoseList run_kf(const std::vector<OdometryStep>& steps, const PoseList& odometry,
                  const ScanMatchingKfSettings& settings, double noise_scale, std::vector<double>& alarms,
                  std::vector<double>& covariance) const {
    const Matrix6d P0 = Matrix6d::Identity() * params_.initial_sigma * params_.initial_sigma;
    ScanMatchingKf3d kf(settings, to_pose6(truth_.front()), P0);
    PoseList estimate{truth_.front()};
    const auto push_covariance = [&](const Matrix6d& P) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) covariance.push_back(P(r, c));
    };
    push_covariance(P0);
    for (std::size_t k = 1; k < params_.scans; ++k) {
      const Vector6d u = to_pose6(odometry[k]).vector() - to_pose6(odometry[k - 1]).vector();  // u(k)
      const Eigen::Isometry3d previous = estimate.back();
      const OdometryStep& step = steps[k - 1];
      const Pose6 z = chain_pose(to_pose6(previous), step.relative);  // the matcher's pose
      const ScanMatchingKfStep s =
          kf.step(u, z, world_hessian(step.hessian, previous, noise_scale), step.converged);
      alarms[k] = s.alarm ? 1.0 : 0.0;
      estimate.push_back(to_isometry(s.pose));
      push_covariance(s.P);
    }
    return estimate;
  }

  /// Why the KF's ellipsoid misses the truth, measured (kalman.cpp's consistency table): H⁻¹ against the
  /// spread of the registrations' own errors, and the same registrations fused as the relative
  /// measurements they are (KfMeasurement::relative), with R = H⁻¹ and with R scaled by that spread.
  void consistency(const std::vector<OdometryStep>& steps, const PoseList& odometry, RunRow& row) const {
    // The registrations' NEES eᵀHe of their true error (6 dof): a covariance H⁻¹ puts its median at χ²₆'s.
    std::vector<double> nees;
    std::vector<Eigen::Vector3d> translation_errors;
    for (std::size_t k = 1; k < params_.scans; ++k) {
      const OdometryStep& step = steps[k - 1];
      if (!step.converged || !step.hessian.allFinite()) continue;
      Vector6d e = to_pose6(step.relative).vector() - to_pose6(relative(truth_[k - 1], truth_[k])).vector();
      for (int i = 3; i < 6; ++i) e[i] = wrap_angle(e[i]);
      const double v = e.dot(step.hessian * e);
      if (std::isfinite(v) && v > 0) nees.push_back(v);
      if (e.allFinite()) translation_errors.push_back(e.head<3>());
    }
    row.values[keys::kRegistrationBias] = largest_bias(translation_errors);
    const double scale = nees.empty() ? kNaN : median_of(nees) / chi_square_quantile(0.5, 6.0);
    row.values[keys::kRegistrationNeesScale] = scale;
    // Gaussian errors of that scale lie beyond χ²₆'s 99 % quantile once in a hundred.
    const double bound = scale * chi_square_quantile(0.99, 6.0);
    row.values[keys::kRegistrationTail] =
        nees.empty() ? kNaN
                     : static_cast<double>(
                           std::count_if(nees.begin(), nees.end(), [&](double v) { return v > bound; })) /
                           static_cast<double>(nees.size());
    ScanMatchingKfSettings relative_fusion = params_.kf;
    relative_fusion.measurement = KfMeasurement::relative;
    const auto score = [&](double noise_scale, const char* inside_key, const char* error_key) {
      std::vector<double> alarms(params_.scans, 0.0), covariance;
      const PoseList estimate = run_kf(steps, odometry, relative_fusion, noise_scale, alarms, covariance);
      row.values[inside_key] = inside_95(estimate, covariance);
      row.values[error_key] = mean_of(horizontal_errors(estimate, truth_));
    };
    score(params_.measurement_noise_scale, keys::kRelativeInside95, keys::kRelativeMeanXy);
    if (std::isfinite(scale)) score(scale, keys::kScaledInside95, keys::kScaledMeanXy);
  }

  /// The share of scans 1 … n − 1 whose true position lies inside the 95 % ellipsoid of `covariance`.
  double inside_95(const PoseList& estimate, const std::vector<double>& covariance) const {
    std::size_t inside = 0, counted = 0;
    for (std::size_t k = 1; k < estimate.size() && 9 * k + 9 <= covariance.size(); ++k) {
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> P(covariance.data() + 9 * k);
      const Eigen::LLT<Eigen::Matrix3d> llt(P);
      if (llt.info() != Eigen::Success) continue;
      const Eigen::Vector3d e = estimate[k].translation() - truth_[k].translation();
      ++counted;
      inside += e.dot(llt.solve(e)) <= chi_square_quantile(0.95, 3.0) ? 1 : 0;
    }
    return counted ? static_cast<double>(inside) / static_cast<double>(counted) : kNaN;
  }

  SequenceParams params_;
  std::vector<RegistrationMethod> methods_;
  std::unique_ptr<Dataset> dataset_;
  PoseList truth_, odometry_;
  synth::OdometrySettings odometry_model_;
  std::vector<PointCloud> scans_;
};

std::vector<RegistrationMethod> read_methods(const ExperimentConfig& config) {
  std::vector<RegistrationMethod> methods;
  for (const auto& m : config.methods) methods.push_back(read_registration_method(m.node, config.file));
  return methods;
}

class SequenceKind : public RunKind {
 public:
  std::string name() const override { return kKind; }

  void validate(const ExperimentConfig& config) const override {
    check_experiment_dataset(config, kKind);
    const SequenceParams params = read_sequence_params(config);
    (void)read_methods(config);
    if (!config.sweep.empty())
      throw InputError(config.file, at_line(yaml_line(config.sweep.front().values.front())),
                       "key 'sweep': the sequence kind has no sweep axes (use repetitions)");
    if (params.odometry == SequenceOdometry::kDataset && config.repetitions > 1)
      throw InputError(config.file, "",
                       "key 'repetitions': with odometry: dataset every repetition would be identical");
    params.report->check_reference(config);
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<SequenceSession>(config, read_sequence_params(config), read_methods(config));
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    const SequenceParams params = read_sequence_params(config);
    return params.report->report(config, params, runs, rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_sequence_kind() {
  return std::make_unique<SequenceKind>();
}

}  // namespace sextant
