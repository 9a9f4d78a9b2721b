#include "sextant/posegraph/loop_closing.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <tbb/parallel_for.h>

#include "sextant/posegraph/relative_pose_factor.hpp"

namespace sextant {

std::string to_string(LoopCandidateSource source) {
  return name_of(kLoopCandidateSourceNames, source);
}

bool from_string(const std::string& text, LoopCandidateSource* out) {
  return from_name(kLoopCandidateSourceNames, text, out);
}

bool LoopClosingSettings::valid(std::string* why) const {
  if (!closure.valid(why) || !descriptor.valid(why) || !graph.valid(why)) return false;
  if (rounds < 1) {
    if (why) *why = "rounds must be ≥ 1";
    return false;
  }
  return true;
}

Matrix6d median_information(const std::vector<Matrix6d>& all) {
  if (all.empty()) return Matrix6d::Identity();
  Matrix6d out;
  std::vector<double> v(all.size());
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      for (std::size_t k = 0; k < all.size(); ++k) v[k] = all[k](r, c);
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
      out(r, c) = v[v.size() / 2];
    }
  Matrix6d L;
  return sqrt_information(out, &L) ? out : Matrix6d::Identity();
}

OdometryGraph odometry_graph(const std::vector<Eigen::Isometry3d>& chained,
                             const std::vector<ChainStep>& steps) {
  // Ω from each step's Hessian (eq. 3.50); a step whose Hessian gives no positive-definite Ω (or
  // that did not converge) gets the median Ω of the others.
  std::vector<Matrix6d> informations(steps.size()), good;
  std::vector<bool> usable(steps.size(), false);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    informations[k] = information_from_pose6_hessian(steps[k].hessian, steps[k].relative);
    Matrix6d L;
    usable[k] = steps[k].converged && sqrt_information(informations[k], &L);
    if (usable[k]) good.push_back(informations[k]);
  }
  OdometryGraph out;
  out.typical_information = median_information(good);
  out.fallback_information = steps.size() - good.size();
  for (const Eigen::Isometry3d& T : chained) out.graph.add_node(T);
  for (std::size_t k = 0; k < steps.size() && k + 1 < chained.size(); ++k)
    out.graph.add_edge(k, k + 1, steps[k].relative, usable[k] ? informations[k] : out.typical_information,
                       EdgeKind::odometry);
  return out;
}

namespace {

/// The candidates of this round not tried before: the descriptor's (first round only), then the
/// proximity search's along `estimate`.
std::vector<ClosureAttempt> new_candidates(const std::vector<Eigen::Isometry3d>& estimate,
                                           const std::vector<PlaceMatch>& places, bool first_round,
                                           const LoopClosingSettings& settings,
                                           std::set<std::pair<std::size_t, std::size_t>>& tried) {
  std::vector<ClosureAttempt> out;
  const auto add = [&](const LoopClosureCandidate& c, LoopCandidateSource source, double distance) {
    if (!tried.insert({c.i, c.j}).second) return;
    ClosureAttempt a;
    a.candidate = c;
    a.source = source;
    a.descriptor_distance = distance;
    out.push_back(a);
  };
  if (settings.source != LoopCandidateSource::descriptor)
    for (const LoopClosureCandidate& c : find_loop_closure_candidates(estimate, settings.closure))
      add(c, LoopCandidateSource::proximity, 1.0);
  if (first_round && settings.source != LoopCandidateSource::proximity)
    for (const PlaceMatch& p : places)
      if (p.j < estimate.size())
        add({p.i, p.j, translation_norm(relative(estimate[p.i], estimate[p.j])), p.guess()},
            LoopCandidateSource::descriptor, p.match.distance);
  return out;
}

}  // namespace

LoopClosingResult close_loops(const PoseGraph& odometry, const std::vector<PlaceMatch>& places,
                              const ClosureRegistration& register_closure,
                              const LoopClosingSettings& settings, Rng& rng) {
  LoopClosingResult out;
  out.graph = odometry;
  // Descriptor candidates carry no translation guess: only a trusted registration closes them.
  LoopClosureSettings descriptor_acceptance = settings.closure;
  descriptor_acceptance.require_trust = true;
  PoseGraphSettings plain = settings.graph;
  plain.loss = RobustLoss::none;
  PoseGraph clean = out.graph;
  out.solve = clean.optimize(settings.graph);
  std::set<std::pair<std::size_t, std::size_t>> tried;
  for (std::size_t round = 0; round < settings.rounds; ++round) {
    std::vector<ClosureAttempt> found = new_candidates(clean.poses(), places, round == 0, settings, tried);
    std::vector<std::uint64_t> seeds(found.size());
    for (auto& s : seeds) s = rng.bits();
    tbb::parallel_for(std::size_t{0}, found.size(), [&](std::size_t k) {
      ClosureAttempt& a = found[k];
      const RegistrationResult r =
          register_closure(a.candidate.i, a.candidate.j, a.candidate.guess, seeds[k]);
      a.decision = judge_loop_closure(
          r, a.candidate,
          a.source == LoopCandidateSource::descriptor ? descriptor_acceptance : settings.closure);
      a.measured = r.T;
      a.seconds = r.seconds;
    });
    for (const ClosureAttempt& a : found) {
      if (!a.decision.accepted) continue;
      out.graph.add_edge(a.candidate.i, a.candidate.j, a.measured, a.decision.information,
                         EdgeKind::loop_closure);
      out.accepted_information.push_back(a.decision.information);
    }
    out.attempts.insert(out.attempts.end(), found.begin(), found.end());
    if (settings.calibrate_information) {
      out.variance = estimate_variance_components(out.graph, settings.graph, settings.variance);
      out.inflation = out.variance.ok ? out.variance.odometry : 1.0;
      out.closure_variance = out.variance.ok ? out.variance.closures : 1.0;
    }
    // The verified closures are trusted first (no robust loss: from the chain, a true closure's
    // error is far outside the robust loss' scale and would be switched off at once), then the
    // robust loss refines from there.
    PoseGraph trusted = with_information_scaled(out.graph, out.inflation, out.closure_variance);
    const PoseGraphReport first = trusted.optimize(plain);
    clean = with_information_scaled(out.graph, out.inflation, out.closure_variance,
                                    first.ok ? trusted.poses() : std::vector<Eigen::Isometry3d>{});
    out.solve = clean.optimize(settings.graph);
    out.solve_seconds += first.seconds + out.solve.seconds;
    out.solve_iterations += first.iterations + out.solve.iterations;
    if (found.empty()) break;
  }
  out.poses = clean.poses();
  return out;
}

}  // namespace sextant
