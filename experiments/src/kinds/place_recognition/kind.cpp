// `place_recognition` (E24): see place_recognition.hpp. The chain, the scans' descriptors and the
// place matches are computed once per experiment (prepare); each run inflates the chain's drift and
// closes its loops with its method's candidate source.
#include <chrono>
#include <cmath>
#include <memory>

#include <tbb/parallel_for.h>

#include "kit/campus.hpp"
#include "kit/row_codec.hpp"
#include "place_recognition/place_recognition.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/loop_detection_metrics.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/posegraph/loop_closing.hpp"

namespace sextant {
namespace place_kind {  // named: the unity build joins this file with other kinds'

constexpr char kKind[] = "place_recognition";

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::size_t scans_of(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  int scans = 0;
  in.read("scans", scans);
  in.finish();
  if (scans < 0 || scans == 1) in.fail("scans", "key 'scans' must be 0 (every scan) or ≥ 2");
  return static_cast<std::size_t>(scans);
}

LoopCandidateSource source_of(const MethodConfig& method, const std::string& file) {
  SettingsReader in(method.node, file);
  std::string name, candidates;
  in.require("name", name);
  in.require("candidates", candidates);
  in.finish();
  LoopCandidateSource source{};
  if (!from_string(candidates, &source))
    in.fail("candidates", "key 'candidates' must be proximity, descriptor or both");
  return source;
}

class PlaceRecognitionSession : public KindSession {
 public:
  PlaceRecognitionSession(const ExperimentConfig& config, std::size_t scans)
      : dataset_(open_campus(config, kKind)), n_(scans ? scans : dataset_.size()), clouds_(n_) {
    for (const MethodConfig& m : config.methods) sources_.push_back(source_of(m, config.file));
    for (std::size_t k = 0; k < n_; ++k) truth_.push_back(*dataset_.ground_truth(k));
    OdometrySettings s;         // ML-NDT on a GBS sample, the campus' odometry as the guess,
    s.map = OdometryMap::scan;  // scan to scan as E20's chain
    s.common_view = false;      // of whole scans, as E20's
    s.seed = config.seed;
    s.initial_pose = truth_.front();
    chain_ = run_odometry(dataset_, s, 0, n_);
    tbb::parallel_for(std::size_t{0}, n_, [&](std::size_t k) { clouds_[k] = dataset_.scan(k); });
    const ScanContextSettings descriptor;
    std::vector<ScanContext> contexts(n_);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n_; ++k) contexts[k] = make_scan_context(clouds_[k], descriptor);
    descriptor_ms_ = 1000.0 * seconds_since(t0) / double(n_);
    const auto t1 = std::chrono::steady_clock::now();
    places_ = find_place_matches(contexts, descriptor);
    search_ms_ = 1000.0 * seconds_since(t1) / double(n_);
  }

  void run(const RunSpec& run, RunRow& row) const override {
    namespace k = place_keys;
    const double drift = run.resolved["point"][kDriftAxis].as<double>() * M_PI / 180.0;
    // The chain with every step turned `drift` more about z than it was.
    std::vector<ChainStep> steps;
    std::vector<Eigen::Isometry3d> chained{chain_.poses.front()};
    for (const OdometryStep& st : chain_.steps) {
      steps.push_back(
          {st.relative * Eigen::AngleAxisd(drift, Eigen::Vector3d::UnitZ()), st.hessian, st.converged});
      chained.push_back(chained.back() * steps.back().relative);
    }
    LoopClosingSettings closing;
    closing.source = sources_.at(run.method_index);
    closing.closure.require_trust = true;
    const ClosureRegistration register_closure = [this](std::size_t i, std::size_t j,
                                                        const Eigen::Isometry3d& guess, std::uint64_t seed) {
      PairRegistrationRequest request;  // ML-NDT, wide basin when the first result is not trusted
      request.init = guess;
      request.seed = seed;
      const PairRegistration r = register_pair(clouds_[i], clouds_[j], request);
      return r.match.result;
    };
    Rng rng(run.seed);
    const auto t0 = std::chrono::steady_clock::now();
    const LoopClosingResult closed =
        close_loops(odometry_graph(chained, steps).graph, places_, register_closure, closing, rng);
    row.values[k::kClosingSeconds] = seconds_since(t0);
    row.values["information_inflation"] = closed.inflation;
    row.values["closure_variance"] = closed.closure_variance;
    row.values["graph_solve_ok"] = closed.solve.ok ? 1.0 : 0.0;
    row.values["graph_solve_iterations"] = closed.solve_iterations;
    row.series["closure_chi2"] = closed.solve.closure_chi2;
    row.series["closure_weight"] = closed.solve.closure_weights;
    for (const ClosureAttempt& a : closed.attempts) {
      row.series["closure_i"].push_back(double(a.candidate.i));
      row.series["closure_j"].push_back(double(a.candidate.j));
      row.series["closure_accepted"].push_back(a.decision.accepted ? 1.0 : 0.0);
      row.series["closure_correction_m"].push_back(a.decision.correction_m);
    }

    const AteResult before = absolute_trajectory_error(chained, truth_);
    const AteResult after = absolute_trajectory_error(closed.poses, truth_);
    row.values[k::kChainedAte] = before.translation.rms;
    row.values[k::kClosedAte] = after.translation.rms;
    row.series[k::kChainedErrors] = before.translation_errors;
    row.series[k::kClosedErrors] = after.translation_errors;
    row.series[k::kChained] = poses_to_series(chained);
    row.series[k::kClosed] = poses_to_series(closed.poses);
    row.series[k::kTruth] = poses_to_series(truth_);

    RevisitSettings revisit;  // a true revisit: within the proximity radius, as far apart in scans
    revisit.radius = closing.closure.radius;
    revisit.min_index_gap = closing.closure.min_index_gap;
    revisit.tolerance = closing.closure.stride;
    std::vector<std::pair<std::size_t, std::size_t>> pairs, accepted;
    for (const ClosureAttempt& a : closed.attempts) {
      pairs.emplace_back(a.candidate.i, a.candidate.j);
      if (a.decision.accepted) accepted.push_back(pairs.back());
    }
    const LoopDetectionScore score = score_loop_candidates(pairs, truth_, revisit);
    row.values[k::kCandidates] = static_cast<double>(score.candidates);
    row.values[k::kPrecision] = score.precision;
    row.values[k::kRecall] = score.recall;
    row.values[k::kAccepted] = static_cast<double>(closed.accepted());
    row.values[k::kAcceptedWrong] =
        static_cast<double>(count_false_closures(accepted, truth_, revisit.radius));
    row.values[k::kPlaceMatches] = static_cast<double>(places_.size());
    row.values[k::kDescriptorMs] = descriptor_ms_;
    row.values[k::kSearchMs] = search_ms_;
  }

 private:
  synth::CampusDataset dataset_;
  std::size_t n_;
  std::vector<LoopCandidateSource> sources_;
  std::vector<Eigen::Isometry3d> truth_;
  OdometryResult chain_;
  std::vector<PointCloud> clouds_;
  std::vector<PlaceMatch> places_;
  double descriptor_ms_ = 0.0, search_ms_ = 0.0;
};

class PlaceRecognitionKind : public RunKind {
 public:
  std::string name() const override { return kKind; }

  void validate(const ExperimentConfig& config) const override {
    const std::size_t scans = scans_of(config);
    for (const MethodConfig& m : config.methods) source_of(m, config.file);
    const SweepAxis* axis = find_axis(config, kDriftAxis);
    if (!axis || config.sweep.size() != 1)
      throw InputError(config.file, "",
                       std::string("key 'sweep': the place_recognition kind sweeps ") + kDriftAxis +
                           " [deg per scan] and nothing else");
    for (const YAML::Node& v : axis->values)
      if (!v.IsScalar() || !std::isfinite(v.as<double>(NAN)))
        throw InputError(config.file, "",
                         std::string("key 'sweep': ") + kDriftAxis + " values must be numbers");
    std::uint64_t seed = 0;
    if (scans > static_cast<std::size_t>(campus_settings(config, kKind, &seed).trajectory.scans))
      throw InputError(config.file, "", "key 'scans': more than the campus' trajectory.scans");
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<PlaceRecognitionSession>(config, scans_of(config));
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return place_recognition_report(config, runs, rows);
  }
};

}  // namespace place_kind

std::unique_ptr<RunKind> make_place_recognition_kind() {
  return std::make_unique<place_kind::PlaceRecognitionKind>();
}

}  // namespace sextant
