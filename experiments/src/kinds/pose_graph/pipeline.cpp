#include "pose_graph/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

#include <tbb/parallel_for.h>

#include "kit/number_format.hpp"
#include "kit/row_codec.hpp"
#include "kit/row_keys.hpp"
#include "pose_graph/row_keys.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/filters/slam_run_failure.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/posegraph/loop_closing.hpp"
#include "sextant/posegraph/relative_pose_factor.hpp"
#include "sextant/synth/odometry.hpp"

namespace sextant {
namespace {

/// ATE (SE(3) Umeyama), Wulf and Kümmerle of one trajectory, as `<prefix>…` values; the per-pose
/// ATE errors and the poses as series.
void put_metrics(const PoseList& estimate, const PoseList& truth, const std::string& prefix, RunRow& row) {
  const AteResult ate = absolute_trajectory_error(estimate, truth, Alignment::se3);
  const WulfResult w = wulf_metric(estimate, truth);
  const KummerleResult k = kummerle_metric(estimate, truth);
  auto& v = row.values;
  v[prefix + keys::kAteM] = ate.status.ok ? ate.translation.rms : kNaN;
  v[prefix + keys::kWulfTranslationM] = w.status.ok ? w.position_rms : kNaN;
  v[prefix + keys::kWulfRotationDeg] = w.status.ok ? w.orientation_rms * kDegPerRad : kNaN;
  v[prefix + keys::kKummerleTranslationM] = k.status.ok ? k.translation_rms : kNaN;
  v[prefix + keys::kKummerleRotationDeg] = k.status.ok ? k.rotation_rms * kDegPerRad : kNaN;
  row.series[prefix + keys::kAteErrors] = ate.translation_errors;
  row.series[prefix + keys::kTrajectory] = poses_to_series(estimate);
}

/// The guesses' odometry: the campus' own, or redrawn from its model with the run seed exactly as
/// the plane_slam kind draws the filters' odometry (kit/plane_slam_record.cpp), so both see one draw.
PoseList guess_odometry(const synth::Campus& campus, const PoseGraphParams& params, std::size_t n,
                        std::uint64_t seed) {
  const PoseList truth(campus.ground_truth.begin(),
                       campus.ground_truth.begin() + static_cast<std::ptrdiff_t>(n));
  if (params.odometry == OdometrySource::kCampus)
    return {campus.odometry.begin(), campus.odometry.begin() + static_cast<std::ptrdiff_t>(n)};
  Rng rng(seed);
  Rng odometry_rng = rng.split();
  return synth::simulate_odometry(truth, campus.settings.odometry, odometry_rng);
}

/// `count` pairs (i, j), |i − j| ≥ the closures' index gap, truly ≥ min_distance apart.
std::vector<std::pair<std::size_t, std::size_t>> false_pairs(const PoseList& truth, const PoseGraphParams& p,
                                                             Rng& rng) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const std::size_t n = truth.size();
  for (int tries = 0; tries < 10000 && out.size() < p.false_closures; ++tries) {
    const auto i = static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)) % n;
    const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)) % n;
    if (j < i + p.loop_closure.min_index_gap) continue;
    if ((truth[i].translation() - truth[j].translation()).norm() < p.false_closure_min_distance) continue;
    out.emplace_back(i, j);
  }
  return out;
}

void put_solve(const PoseGraphReport& r, const std::string& prefix, RunRow& row) {
  row.values[prefix + "ok"] = r.ok ? 1.0 : 0.0;
  row.values[prefix + keys::kIterations] = r.iterations;
  row.values[prefix + keys::kSeconds] = r.seconds;
  row.values[prefix + "initial_cost"] = r.initial_cost;
  row.values[prefix + "final_cost"] = r.final_cost;
}

}  // namespace

PreloadedCampus::PreloadedCampus(const synth::Campus& campus, std::size_t scans, bool with_landmarks) {
  metadata_ = {"campus", "synthetic", {}, scans, true, true, {}};
  data_.campus = &campus;
  data_.clouds.resize(scans);
  if (with_landmarks) data_.visible.resize(scans);
  tbb::parallel_for(std::size_t{0}, scans, [&](std::size_t k) {
    synth::SimulatedScan s = campus.scan(k);
    data_.clouds[k] = std::move(s.cloud);
    if (with_landmarks) data_.visible[k] = std::move(s.visible);
  });
}

PointCloud PreloadedCampus::scan(std::size_t i, ScanLoadReport* report) const {
  const PointCloud& cloud = data_.clouds.at(i);
  if (report) report->points_read = cloud.size();
  return cloud;
}

std::optional<Eigen::Isometry3d> PreloadedCampus::odometry(std::size_t i) const {
  return data_.campus->odometry.at(i);
}

std::optional<Eigen::Isometry3d> PreloadedCampus::ground_truth(std::size_t i) const {
  return data_.campus->ground_truth.at(i);
}

void run_pose_graph_method(const PreloadedCampus& data, const PoseGraphParams& params,
                           const RegistrationSpec& method, const MatcherSpec& closure, std::uint64_t seed,
                           RunRow& row) {
  const std::size_t n = data.size();
  const PoseList truth(data.campus().ground_truth.begin(),
                       data.campus().ground_truth.begin() + static_cast<std::ptrdiff_t>(n));
  OdometrySettings s;
  s.registration = {matcher_choice(method.matcher), sampler_factory(method.sampler)};
  s.guess = params.guess;
  s.map = OdometryMap::scan;  // E20 chains scan-to-scan registrations (its edges are pairwise)
  s.seed = seed;
  s.odometry = guess_odometry(data.campus(), params, n, seed);
  s.initial_pose = truth.front();
  s.recover = false;      // E20 handles wrong odometry edges itself (robust loss, trusted-first solve)
  s.common_view = false;  // its edges register the whole scans, as its measured verdicts did
  const OdometryResult odometry = run_odometry(data, s, 0, n);
  Rng rng(seed ^ 0x5E20C105E5ULL);

  // The graph over the chain (one edge per registration, Ω from its Hessian, eq. 3.50) and its
  // loops closed in rounds from the proximity search (posegraph/loop_closing.hpp).
  std::vector<ChainStep> chain;
  double registration_seconds = 0.0, not_converged = 0.0;
  for (const OdometryStep& st : odometry.steps) {
    registration_seconds += st.seconds;
    row.series["step_mean_score"].push_back(st.matched_points ? st.score / double(st.matched_points) : kNaN);
    not_converged += st.converged ? 0.0 : 1.0;
    chain.push_back({st.relative, st.hessian, st.converged});
  }
  const OdometryGraph odometry_edges = odometry_graph(odometry.poses, chain);
  LoopClosingSettings closing;
  closing.source = LoopCandidateSource::proximity;
  closing.closure = params.loop_closure;
  closing.graph = params.graph;
  closing.rounds = params.closure_rounds;
  closing.calibrate_information = params.calibrate_information;
  const ClosureRegistration register_closure =
      [&](std::size_t i, std::size_t j, const Eigen::Isometry3d& guess, std::uint64_t sampler_seed) {
        const auto matcher = make_matcher(closure);
        const auto sampler = make_sampler(method.sampler);
        Rng local(sampler_seed);
        const PairMatch m = match_pair(*matcher, *sampler, data.clouds()[i], data.clouds()[j], guess, local);
        RegistrationResult r = m.result;
        r.seconds += m.reference_seconds + m.sampling_seconds;
        return r;
      };
  const LoopClosingResult closed = close_loops(odometry_edges.graph, {}, register_closure, closing, rng);
  PoseGraph graph = closed.graph;
  const std::vector<Matrix6d>& accepted_information = closed.accepted_information;
  const Matrix6d& typical = odometry_edges.typical_information;
  PoseGraphSettings plain_settings = params.graph;
  plain_settings.loss = RobustLoss::none;
  double closure_seconds = 0.0;
  for (const ClosureAttempt& c : closed.attempts) closure_seconds += c.seconds;

  // False closures: "same place" between truly distant poses, with a typical closure's information.
  const Matrix6d false_information =
      accepted_information.empty() ? typical : median_information(accepted_information);
  const auto pairs = false_pairs(truth, params, rng);
  for (const auto& [i, j] : pairs)
    graph.add_edge(i, j, Eigen::Isometry3d::Identity(), false_information, EdgeKind::loop_closure);
  // The false closure arrives into the solved map (as it would in incremental mapping).
  PoseGraph robust = with_information_scaled(graph, closed.inflation, closed.closure_variance, closed.poses),
            plain = robust;
  const PoseGraphReport robust_report = robust.optimize(params.graph);
  const PoseGraphReport plain_report = plain.optimize(plain_settings);

  put_metrics(odometry.poses, truth, "chained_", row);
  put_metrics(closed.poses, truth, "graph_", row);
  put_metrics(robust.poses(), truth, "false_robust_", row);
  put_metrics(plain.poses(), truth, "false_plain_", row);
  row.series[keys::kTruth] = poses_to_series(truth);
  put_solve(closed.solve, "graph_solve_", row);
  row.values[keys::kGraphSolveSeconds] = closed.solve_seconds;  // every round's solve
  row.values[keys::kGraphSolveIterations] = closed.solve_iterations;
  put_solve(robust_report, "false_robust_solve_", row);
  put_solve(plain_report, "false_plain_solve_", row);
  auto& v = row.values;
  v[keys::kScans] = static_cast<double>(n);
  v[keys::kRegistrationSeconds] = registration_seconds;
  v[keys::kNotConverged] = not_converged;
  v[keys::kFallbackInformation] = static_cast<double>(odometry_edges.fallback_information);
  v[keys::kClosureSeconds] = closure_seconds;
  v[keys::kInformationInflation] = closed.inflation;
  v["closure_variance"] = closed.closure_variance;
  v[keys::kCandidates] = static_cast<double>(closed.attempts.size());
  v[keys::kAccepted] = static_cast<double>(accepted_information.size());
  v[keys::kFalseClosures] = static_cast<double>(pairs.size());
  std::size_t accepted_index = 0;
  for (const ClosureAttempt& c : closed.attempts) {
    auto& se = row.series;
    se["closure_i"].push_back(static_cast<double>(c.candidate.i));
    se[keys::kClosureJ].push_back(static_cast<double>(c.candidate.j));
    se[keys::kClosureRejection].push_back(static_cast<double>(c.decision.rejection));
    se["closure_mean_score"].push_back(c.decision.mean_score);
    se["closure_correction_m"].push_back(c.decision.correction_m);
    // How right the registration was (never used to decide): its error against the true relative pose.
    const Eigen::Isometry3d error =
        relative(relative(truth[c.candidate.i], truth[c.candidate.j]), c.measured);
    se["closure_true_error_m"].push_back(translation_norm(error));
    se["closure_true_error_deg"].push_back(rotation_angle(error) * kDegPerRad);
    const bool weighted = c.decision.accepted && accepted_index < closed.solve.closure_weights.size();
    se[keys::kClosureWeight].push_back(weighted ? closed.solve.closure_weights[accepted_index] : kNaN);
    if (c.decision.accepted) ++accepted_index;
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    row.series[keys::kFalseI].push_back(static_cast<double>(pairs[k].first));
    row.series[keys::kFalseJ].push_back(static_cast<double>(pairs[k].second));
    const std::size_t index = accepted_information.size() + k;
    row.series[keys::kFalseWeight].push_back(
        index < robust_report.closure_weights.size() ? robust_report.closure_weights[index] : kNaN);
  }
}

void run_filter_method(const PreloadedCampus& data, const PoseGraphParams& params,
                       const PlaneSlamMethod& method, std::uint64_t seed, const std::string& file,
                       RunRow& row) {
  const std::size_t n = method.scans ? std::min(method.scans, data.size()) : data.size();
  const PlaneSlamSettings settings = plane_slam_settings(params.filters, method, kNaN, file);
  const RecordedRun run = record_plane_slam(data.filter_data(), params.filters, settings, n, seed);
  PoseList estimate, truth;
  double failed = 0.0;
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const Vector6d& x = run.steps[k].pose;
    truth.push_back(data.campus().ground_truth[k]);
    estimate.push_back(x.allFinite() ? to_isometry(Pose6::from_vector(x)) : truth.back());
    failed += run.steps[k].ok ? 0.0 : 1.0;
  }
  const std::string failure =
      slam_run_failure(run.map.size(), static_cast<std::size_t>(failed), run.steps.size());
  if (!failure.empty()) throw std::runtime_error(failure);
  put_metrics(estimate, truth, "filter_", row);
  row.series[keys::kTruth] = poses_to_series(truth);
  row.values[keys::kScans] = static_cast<double>(n);
  row.values[keys::kFailedSteps] = failed;
  double motion = 0.0, measurement = 0.0;
  for (const RecordedStep& st : run.steps) motion += st.motion_seconds, measurement += st.measurement_seconds;
  row.values["filter_seconds"] = motion + measurement;
}

}  // namespace sextant
