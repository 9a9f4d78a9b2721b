// `plane_slam`: one run = one filter over the first scans of the
// synthetic campus at one sweep point (p0_scale) and repetition (kit/plane_slam_record.hpp). Each
// row holds per scan the position / rotation error against the ground truth, the NEES of the
// pose, the motion- and measurement-update times and the map size; the estimated, true and
// dead-reckoned trajectories with the pose covariances; the final map; the information-matrix
// block patterns asked for; and as values the maxima, finals, Wulf and Kümmerle metrics.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>
#include <Eigen/Cholesky>

#include "kit/campus.hpp"
#include "kit/plane_slam_record.hpp"
#include "kit/row_keys.hpp"
#include "plane_slam/layouts/layouts.hpp"
#include "plane_slam/report.hpp"
#include "plane_slam/row_keys.hpp"
#include "sextant/core/chi_square.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/filters/slam_run_failure.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant {
namespace {

std::vector<PlaneSlamMethod> read_methods(const ExperimentConfig& config) {
  std::vector<PlaneSlamMethod> methods;
  for (const auto& m : config.methods) methods.push_back(read_plane_slam_method(m.node, config.file));
  return methods;
}

/// ‖(α, β, γ) − (α, β, γ)*‖ with each difference wrapped (eq. 6.3) [rad].
double rotation_error(const Vector6d& a, const Vector6d& b) {
  return Eigen::Vector3d(wrap_angle(a[3] - b[3]), wrap_angle(a[4] - b[4]), wrap_angle(a[5] - b[5])).norm();
}

/// NEES of the pose: eᵀ P⁻¹ e with e = x̂ − x (angles wrapped); NaN when P is not positive definite.
double pose_nees(const Vector6d& estimate, const Vector6d& truth, const Matrix6d& P) {
  Vector6d e = estimate - truth;
  for (int i = 3; i < 6; ++i) e[i] = wrap_angle(e[i]);
  if (!P.allFinite() || !e.allFinite()) return kNaN;
  const Eigen::LLT<Matrix6d> llt(P);
  if (llt.info() != Eigen::Success) return kNaN;
  return e.dot(llt.solve(e));
}

void put_max(const std::vector<double>& v, RunRow& row, const std::string& value, const std::string& at) {
  double best = kNaN, where = kNaN;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::isfinite(v[k]) && !(v[k] <= best)) {
      best = v[k];
      where = static_cast<double>(k);
    }
  row.values[value] = best;
  if (!at.empty()) row.values[at] = where;
}

void put_benchmarks(const PoseList& estimate, const PoseList& truth, const std::string& prefix, RunRow& row) {
  const WulfResult w = wulf_metric(estimate, truth);
  const KummerleResult k = kummerle_metric(estimate, truth);
  row.values[prefix + keys::kWulfTranslationM] = w.status.ok ? w.position_rms : kNaN;
  row.values[prefix + keys::kWulfRotationDeg] = w.status.ok ? w.orientation_rms * kDegPerRad : kNaN;
  row.values[prefix + keys::kKummerleTranslationM] = k.status.ok ? k.translation_rms : kNaN;
  row.values[prefix + keys::kKummerleRotationDeg] = k.status.ok ? k.rotation_rms * kDegPerRad : kNaN;
}

/// Extracted landmarks: the mean per-scan times of extraction, association, filter (predict +
/// update + augment) and registration (hybrid SLAM), and the registration's share of the rest
/// (`registration_extra`: 0.2 = a step costs 20 % more than without the registration).
void put_step_costs(RunRow& row) {
  auto& s = row.series;
  auto& v = row.values;
  v["extraction_ms_mean"] = mean_of(s[keys::kExtractionMs]);
  v["association_ms_mean"] = mean_of(s[keys::kAssociationMs]);
  v["filter_ms_mean"] = v["motion_ms_mean"] + v["measurement_ms_mean"];
  v["registration_ms_mean"] = mean_of(s[keys::kRegistrationMs]);
  v["registration_extra"] =
      v["registration_ms_mean"] / (v["extraction_ms_mean"] + v["association_ms_mean"] + v["filter_ms_mean"]);
  double matched = 0.0, judged = 0.0;
  for (double m : s["matched_motion"])
    if (m >= 0.0) matched += m, ++judged;
  v[keys::kMotionMatchedFraction] = judged > 0.0 ? matched / judged : kNaN;
}

/// The estimated vertical planes as top-down segments over their true landmark's extent: each
/// polygon vertex projected onto the estimated plane's trace (x, y, z̄) → 4 numbers per segment.
std::vector<double> map_segments(const RecordedRun& r, const synth::Campus& campus) {
  std::vector<double> out;
  for (std::size_t i = 0; i < r.map.size() && i < r.map_truth.size(); ++i) {
    if (r.map_truth[i] < 0) continue;
    const Eigen::Vector4d& m = r.map[i];
    const Eigen::Vector2d nxy = m.head<2>();
    if (!m.allFinite() || nxy.norm() < 0.7 * m.head<3>().norm()) continue;  // not vertical: roofs
    const synth::Landmark& l = campus.world->landmarks[static_cast<std::size_t>(r.map_truth[i])];
    double z = 0.0;
    for (const Eigen::Vector3d& v : l.polygon) z += v.z() / static_cast<double>(l.polygon.size());
    const Eigen::Vector2d n = nxy.normalized(), t(-n.y(), n.x());
    const double d = (m[3] - m[2] * z) / nxy.norm();
    double lo = INFINITY, hi = -INFINITY;
    for (const Eigen::Vector3d& v : l.polygon) {
      lo = std::min(lo, t.dot(v.head<2>()));
      hi = std::max(hi, t.dot(v.head<2>()));
    }
    if (!(hi > lo)) continue;
    const Eigen::Vector2d a = d * n + lo * t, b = d * n + hi * t;
    out.insert(out.end(), {a.x(), a.y(), b.x(), b.y()});
  }
  return out;
}

void fill_row(const RecordedRun& r, const synth::Campus& campus, const PlaneSlamParams& params,
              LandmarkSource landmarks, RunRow& row) {
  const std::size_t n = r.steps.size();
  const double bound = chi_square_quantile(params.nees_probability, 6.0);
  auto& s = row.series;
  PoseList estimate, truth, odometry;
  std::size_t inconsistent = 0, judged = 0, failed = 0, updates = 0, gated = 0;
  double first_failure = kNaN;
  for (std::size_t k = 0; k < n; ++k) {
    const RecordedStep& st = r.steps[k];
    const Vector6d t = to_pose6(campus.ground_truth[k]).vector(), o = r.odometry[k].vector();
    const bool finite = st.pose.allFinite();
    s[keys::kErrorM].push_back(finite ? (st.pose.head<3>() - t.head<3>()).norm() : kNaN);
    s[keys::kRotationErrorDeg].push_back(finite ? rotation_error(st.pose, t) * kDegPerRad : kNaN);
    s[keys::kOdometryErrorM].push_back((o.head<3>() - t.head<3>()).norm());
    s[keys::kOdometryRotationErrorDeg].push_back(rotation_error(o, t) * kDegPerRad);
    const double nees = pose_nees(st.pose, t, st.covariance);
    s[keys::kNees].push_back(nees);
    if (st.has_marginal) s[keys::kNeesMarginal].push_back(pose_nees(st.pose, t, st.marginal));
    if (st.active >= 0) s["active_landmarks"].push_back(st.active);
    if (std::isfinite(nees)) {
      ++judged;
      if (nees > bound) ++inconsistent;
    }
    s[keys::kMotionMs].push_back(1e3 * st.motion_seconds);
    s[keys::kMeasurementMs].push_back(1e3 * st.measurement_seconds);
    s[keys::kStepMs].push_back(1e3 * (st.motion_seconds + st.measurement_seconds));
    s[keys::kMapSize].push_back(static_cast<double>(st.map_size));
    if (landmarks == LandmarkSource::kExtracted) {
      s[keys::kExtractionMs].push_back(1e3 * st.extraction_seconds);
      s[keys::kAssociationMs].push_back(1e3 * st.association_seconds);
      s[keys::kRegistrationMs].push_back(1e3 * st.registration_seconds);
      s["matched_motion"].push_back(st.matched_motion);
    }
    for (int i = 0; i < 6; ++i) {
      s[keys::kTrajectory].push_back(st.pose[i]);
      s[keys::kTruth].push_back(t[i]);
      s[keys::kOdometry].push_back(o[i]);
    }
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) s[keys::kPositionCovariance].push_back(st.covariance(i, j));
    if (!st.ok) {
      ++failed;
      if (!std::isfinite(first_failure)) first_failure = static_cast<double>(k);
    }
    updates += st.updated;
    gated += st.gated;
    estimate.push_back(finite ? to_isometry(Pose6::from_vector(st.pose)) : campus.ground_truth[k]);
    truth.push_back(campus.ground_truth[k]);
    odometry.push_back(to_isometry(r.odometry[k]));
  }
  // A filter that failed on most steps is no result — unless failing is what the experiment
  // measures (E13: the UKF loses positive definiteness beyond P0 × 1e3, §5.2.1.2).
  const std::string failure = slam_run_failure(r.map.size(), failed, n);
  const bool measured = params.failures_are_results && failed > 0 && !r.map.empty();
  if (!failure.empty() && !measured) throw std::runtime_error(failure);
  row.values[keys::kEndedByFailures] = failure.empty() ? 0.0 : 1.0;
  for (const Eigen::Vector4d& m : r.map)
    for (int i = 0; i < 4; ++i) s["map"].push_back(m[i]);
  for (int id : r.map_truth) s["map_truth"].push_back(id);
  s[keys::kMapSegments] = map_segments(r, campus);
  for (std::size_t i = 0; i < r.information.size(); ++i) {
    const InformationPattern& p = r.information[i];
    s["information_" + std::to_string(i)] = p.links;
    row.values["information_" + std::to_string(i) + "_scan"] = static_cast<double>(p.scan);
    row.values["information_" + std::to_string(i) + "_landmarks"] = static_cast<double>(p.landmarks);
  }

  auto& v = row.values;
  v[keys::kScans] = static_cast<double>(n);
  put_max(s[keys::kErrorM], row, "max_error_m", "max_error_scan");
  put_max(s[keys::kRotationErrorDeg], row, "max_rotation_deg", "");
  put_max(s[keys::kOdometryErrorM], row, "odometry_max_error_m", "odometry_max_error_scan");
  v["final_error_m"] = s[keys::kErrorM].back();
  v["final_rotation_deg"] = s[keys::kRotationErrorDeg].back();
  v["mean_error_m"] = mean_of(s[keys::kErrorM]);
  v[keys::kOdometryFinalErrorM] = s[keys::kOdometryErrorM].back();
  v[keys::kOdometryMeanErrorM] = mean_of(s[keys::kOdometryErrorM]);
  v["mean_nees"] = mean_of(s[keys::kNees]);
  if (s.count(keys::kNeesMarginal)) v["mean_nees_marginal"] = mean_of(s[keys::kNeesMarginal]);
  if (s.count("active_landmarks")) put_max(s["active_landmarks"], row, "max_active_landmarks", "");
  v["relocations"] = static_cast<double>(r.relocations);
  v["skipped_relocations"] = static_cast<double>(r.skipped_relocations);
  v[keys::kNeesBound] = bound;
  v["inconsistent_fraction"] =
      judged ? static_cast<double>(inconsistent) / static_cast<double>(judged) : kNaN;
  v[keys::kFailedSteps] = static_cast<double>(failed);
  v[keys::kFirstFailureScan] = first_failure;
  v[keys::kNotPositiveDefinite] = static_cast<double>(r.summary.not_positive_definite);
  v[keys::kCholeskyFailures] = static_cast<double>(r.summary.cholesky_failures);
  v["singular_innovations"] = static_cast<double>(r.summary.singular_innovations);
  v[keys::kMapSize] = static_cast<double>(r.map.size());
  v[keys::kUpdates] = static_cast<double>(updates);
  v["gated"] = static_cast<double>(gated);
  v["motion_ms_mean"] = mean_of(s[keys::kMotionMs]);
  v["measurement_ms_mean"] = mean_of(s[keys::kMeasurementMs]);
  if (landmarks == LandmarkSource::kExtracted) put_step_costs(row);
  put_benchmarks(estimate, truth, "", row);
  put_benchmarks(odometry, truth, "odometry_", row);
  const KummerleResult k = kummerle_metric(estimate, truth);
  for (double e : k.translation_errors) s[keys::kKummerleTranslationM].push_back(e);
  for (double e : k.rotation_errors) s[keys::kKummerleRotationDeg].push_back(e * kDegPerRad);
  const KummerleResult ko = kummerle_metric(odometry, truth);
  for (double e : ko.translation_errors) s["odometry_kummerle_translation_m"].push_back(e);
  for (double e : ko.rotation_errors) s["odometry_kummerle_rotation_deg"].push_back(e * kDegPerRad);
  if (params.compare_scans >= 2 && params.compare_scans <= n) {
    const auto prefix = [&](const PoseList& p) {
      return PoseList(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(params.compare_scans));
    };
    put_benchmarks(prefix(estimate), prefix(truth), "prefix_", row);
    put_benchmarks(prefix(odometry), prefix(truth), "prefix_odometry_", row);
  }
}

/// The campus from `params.first` on (the whole campus when it is 0).
synth::Campus campus_from(synth::Campus campus, const PlaneSlamParams& params, const std::string& file) {
  if (params.first == 0) return campus;
  if (params.first >= campus.size())
    throw InputError(file, "",
                     "key 'first': scan " + std::to_string(params.first) + " is past the campus' " +
                         std::to_string(campus.size()) + " scans");
  return synth::campus_window(campus, params.first, campus.size() - params.first);
}

class PlaneSlamSession : public KindSession {
 public:
  PlaneSlamSession(const ExperimentConfig& config, PlaneSlamParams params,
                   std::vector<PlaneSlamMethod> methods)
      : file_(config.file),
        params_(std::move(params)),
        methods_(std::move(methods)),
        campus_(campus_from(open_campus(config, "plane_slam"), params_, config.file)) {
    const std::size_t scans = needed_scans();
    data_.campus = &campus_;
    bool visible = false, clouds = false;  // what the methods' landmark sources need
    for (const PlaneSlamMethod& m : methods_)
      (landmark_source(params_, m) == LandmarkSource::kTrue ? visible : clouds) = true;
    if (visible) data_.visible.resize(scans);
    if (clouds) data_.clouds.resize(scans);
    tbb::parallel_for(std::size_t{0}, scans, [&](std::size_t k) {
      synth::SimulatedScan scan = campus_.scan(k);
      if (visible) data_.visible[k] = std::move(scan.visible);
      if (clouds) data_.clouds[k] = std::move(scan.cloud);
    });
  }

  void run(const RunSpec& run, RunRow& row) const override {
    const PlaneSlamMethod& method = methods_.at(run.method_index);
    const auto it = run.point.find(kP0ScaleAxis);
    const double p0 = it == run.point.end() ? kNaN : std::stod(it->second);
    const PlaneSlamSettings settings = plane_slam_settings(params_, method, p0, file_);
    const std::size_t scans = method.scans ? std::min(method.scans, sequence_scans()) : sequence_scans();
    fill_row(record_plane_slam(data_, params_, settings, scans, run.seed, method), campus_, params_,
             landmark_source(params_, method), row);
  }

 private:
  std::size_t sequence_scans() const { return params_.scans ? params_.scans : campus_.size(); }
  std::size_t needed_scans() const {
    if (sequence_scans() > campus_.size())
      throw InputError(file_, "",
                       "key 'scans': " + std::to_string(sequence_scans()) + " is past the campus' " +
                           std::to_string(campus_.size()) + " scans");
    return sequence_scans();
  }

  std::string file_;
  PlaneSlamParams params_;
  std::vector<PlaneSlamMethod> methods_;
  synth::Campus campus_;
  CampusScans data_;
};

class PlaneSlamKind : public RunKind {
 public:
  std::string name() const override { return "plane_slam"; }

  void validate(const ExperimentConfig& config) const override {
    const PlaneSlamParams params = read_plane_slam_params(config);
    const PlaneSlamLayout& layout = plane_slam_layout(config, params);
    for (const PlaneSlamMethod& m : read_methods(config)) {
      (void)plane_slam_settings(params, m, kNaN, config.file);
      if (m.motion == MotionSource::kFbmlndt && landmark_source(params, m) != LandmarkSource::kExtracted)
        throw InputError(config.file, "",
                         "method '" + m.name +
                             "': motion: fbmlndt shares the plane extraction, it needs "
                             "params.landmarks: extracted");
    }
    check_plane_slam_sweep(config);
    std::uint64_t seed = 0;
    const synth::CampusSettings campus = campus_settings(config, "plane_slam", &seed);
    if (params.first + params.scans > static_cast<std::size_t>(campus.trajectory.scans)) {
      SettingsReader in(config.params, config.file);  // the message names the key's line
      if (params.first) in.fail("first", "key 'first' + key 'scans': more than the campus' trajectory.scans");
      in.fail("scans", "key 'scans': more than the campus' trajectory.scans");
    }
    check_plane_slam_claims(config, params);
    layout.check_reference(config);
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<PlaneSlamSession>(config, read_plane_slam_params(config), read_methods(config));
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    const PlaneSlamParams params = read_plane_slam_params(config);
    const PlaneSlamLayout& layout = plane_slam_layout(config, params);
    const PlaneSlamRows data = collect_plane_slam_rows(config, runs, rows);
    return layout.report(config, params, data);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_plane_slam_kind() {
  return std::make_unique<PlaneSlamKind>();
}

}  // namespace sextant
