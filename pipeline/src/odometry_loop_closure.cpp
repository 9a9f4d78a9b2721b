#include "sextant/pipeline/odometry_loop_closure.hpp"

#include <chrono>
#include <iomanip>
#include <sstream>

#include <tbb/parallel_for.h>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/pipeline/odometry_output.hpp"
#include "sextant/pipeline/steps_table.hpp"

namespace sextant {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

OdometryLoopClosure close_odometry_loops(const Dataset& dataset, std::size_t first, std::size_t count,
                                         const OdometryResult& chain, const OdometrySettings& settings,
                                         LoopCandidateSource source) {
  const auto t0 = std::chrono::steady_clock::now();
  OdometryLoopClosure out;
  LoopClosingSettings closing;
  closing.source = source;
  closing.closure.require_trust = true;  // a user's sequence: only trusted registrations close loops

  std::vector<PointCloud> scans(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t k) {
    scans[k] = registered_scan(dataset, chain, first, k, settings.min_range);  // deskewed as the chain did
  });
  std::vector<PlaceMatch> places;
  if (source != LoopCandidateSource::proximity) {
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<ScanContext> contexts(count);
    tbb::parallel_for(std::size_t{0}, count,
                      [&](std::size_t k) { contexts[k] = make_scan_context(scans[k], closing.descriptor); });
    places = find_place_matches(contexts, closing.descriptor);
    out.descriptor_seconds = seconds_since(t1);
  }
  out.place_matches = places.size();

  std::vector<ChainStep> steps;
  for (const OdometryStep& st : chain.steps) steps.push_back({st.relative, st.hessian, st.converged});
  const OdometryGraph graph = odometry_graph(chain.poses, steps);
  const ClosureRegistration register_closure = [&](std::size_t i, std::size_t j,
                                                   const Eigen::Isometry3d& guess, std::uint64_t seed) {
    PairRegistrationRequest request;
    request.matcher = settings.registration.matcher;
    request.sampler = settings.registration.sampler;
    request.init = guess;
    request.seed = seed;
    const PairRegistration r = register_pair(scans[i], scans[j], request);
    RegistrationResult result = r.match.result;
    result.seconds += r.match.reference_seconds + r.match.sampling_seconds;
    return result;
  };
  Rng rng(settings.seed ^ 0x5E24C105E5ULL);
  out.closing = close_loops(graph.graph, places, register_closure, closing, rng);
  out.seconds = seconds_since(t0);
  return out;
}

std::vector<SourceScore> score_sources(const OdometryLoopClosure& closure,
                                       const std::vector<Eigen::Isometry3d>& truth) {
  const LoopClosingSettings defaults;
  RevisitSettings revisit;
  revisit.radius = defaults.closure.radius;
  revisit.min_index_gap = defaults.closure.min_index_gap;
  revisit.tolerance = defaults.closure.stride;
  std::vector<SourceScore> out;
  for (const LoopCandidateSource source : {LoopCandidateSource::proximity, LoopCandidateSource::descriptor}) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs, accepted;
    SourceScore score;
    score.source = source;
    for (const ClosureAttempt& a : closure.closing.attempts) {
      if (a.source != source) continue;
      pairs.emplace_back(a.candidate.i, a.candidate.j);
      if (a.decision.accepted) accepted.push_back(pairs.back());
    }
    if (pairs.empty()) continue;
    score.accepted = accepted.size();
    score.accepted_wrong = count_false_closures(accepted, truth, revisit.radius);
    score.candidates = score_loop_candidates(pairs, truth, revisit);
    out.push_back(score);
  }
  return out;
}

void write_loop_closures_csv(const std::filesystem::path& file, std::size_t first,
                             const OdometryLoopClosure& closure,
                             const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  std::ostringstream out;
  out << "from_scan,to_scan,source,descriptor_distance,estimate_distance_m,accepted,reason,"
         "mean_score,matched_fraction,correction_m,correction_deg,seconds,error_m,error_deg\n";
  out << std::setprecision(9);
  for (const ClosureAttempt& a : closure.closing.attempts) {
    const LoopClosureDecision& d = a.decision;
    out << first + a.candidate.i << ',' << first + a.candidate.j << ',' << to_string(a.source) << ','
        << (a.source == LoopCandidateSource::descriptor ? a.descriptor_distance : kNaN) << ','
        << a.candidate.distance << ',' << (d.accepted ? 1 : 0) << "," << csv_free_text(d.reason) << ","
        << d.mean_score << ',' << d.matched_fraction << ',' << d.correction_m << ',' << d.correction_deg
        << ',' << a.seconds;
    if (truth) {
      // How right the verifying registration was (never used to decide).
      const Eigen::Isometry3d error =
          relative(relative((*truth)[a.candidate.i], (*truth)[a.candidate.j]), a.measured);
      out << ',' << translation_norm(error) << ',' << rotation_angle(error) * kDegPerRad;
    } else {
      out << ",,";
    }
    out << '\n';
  }
  write_file_atomically(file, out.str());
}

}  // namespace sextant
