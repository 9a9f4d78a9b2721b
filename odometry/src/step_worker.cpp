// One odometry step's registrations (step_worker.hpp).
#include "step_worker.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include <fmt/format.h>

#include "sextant/core/rng.hpp"
#include "sextant/matchers/horizon_check.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/odometry/sequence_trust.hpp"
#include "sextant/odometry/suspect_choice.hpp"

namespace sextant::odometry_detail {
namespace {

/// Fits within this factor of each other count as equal when no registration is trusted: the
/// sequence check's own tolerance (SequenceTrustSettings::fit_factor) [ratio].
constexpr double kSuspectFitBand = SequenceTrustSettings{}.fit_factor;

}  // namespace

StepWorker::StepWorker(const OdometrySettings& s)
    : matcher_(s.registration.matcher.make()), sampler_(s.registration.sampler()), settings_(s) {
  if (!s.recover) return;
  const MatcherFactory& wide = s.registration.matcher.make_wide;
  wide_basin_ = static_cast<bool>(wide);
  recovery_ = wide ? wide() : s.registration.matcher.make();
}

OdometryStep StepWorker::first_try(const PointCloud& reference, const PointCloud& input,
                                   const Eigen::Isometry3d& guess, std::uint64_t seed, StepContext context) {
  Rng rng(seed);
  context_ = std::move(context);
  const SampledInput sample = sample_input(*sampler_, input, rng);
  Matcher& matcher = context_.search && recovery_ ? *recovery_ : *matcher_;
  PairMatch m = match_sample(matcher, sample, reference, guess, quality());
  matcher_reference_ = &matcher == matcher_.get() ? &reference : nullptr;
  recovery_reference_ = &matcher == recovery_.get() ? &reference : nullptr;
  searched_ = &matcher == recovery_.get() && wide_basin_;
  // Every prior the sequence offers is a start; their solutions are the result's alternatives, and
  // two that pass the checks far apart make it ambiguous (registration_quality.hpp).
  for (const Eigen::Isometry3d& prior : context_.other_priors) {
    PairMatch other = align_sample(matcher, sample, prior, quality());
    m.result.seconds += other.result.seconds;
    for (RegistrationResult& alternative : other.result.alternatives)
      m.result.alternatives.push_back(std::move(alternative));
    other.result.alternatives.clear();
    other.result.trace.clear();
    m.result.alternatives.push_back(std::move(other.result));
  }
  if (!context_.other_priors.empty())
    m.result.quality = assess_registration(m.result, sample.points, quality());
  settle_rivals(local(reference, matcher), sample, m);
  answers_.clear();
  disputed_.clear();
  refuted_.clear();
  elsewhere_.clear();
  OdometryStep step = to_step(m, reference, guess);
  confirm_above_horizon(step, reference, input, sample.points, matcher);
  remember(m, sample.points);
  step.first_trust = step.quality.trust;
  step.first_relative = step.relative;
  return step;
}

void StepWorker::recover(OdometryStep& step, const PointCloud& reference, const PointCloud& input,
                         const std::vector<Eigen::Isometry3d>& starts, std::uint64_t seed,
                         const SequenceTrust& sequence) {
  if (step.trusted() || !recovery_ || starts.empty()) return;  // recovery_: null when it is off
  double seconds = step.seconds;
  // The registrations whose only flaw is their fit: converged, enough overlap, every direction
  // constrained. The first registration counts as it was judged on its own (a sequence check may
  // have flagged an absolutely sound one). An answer the platform could not reach stays a candidate
  // (docs/matcher_defaults.md, "A motion no platform makes": leaving it out chained a pose turned 179°).
  std::vector<OdometryStep> suspects;
  const auto consider = [&](const OdometryStep& candidate, Trust absolute) {
    if (candidate.converged && (absolute == Trust::kSuspect || absolute == Trust::kOk))
      suspects.push_back(candidate);
  };
  consider(step, step.first_trust);
  // Every answer of this step so far (answers_: the first registration and its alternatives): a
  // trusted recovery far from one of them corrects it only when it fits clearly better (beyond the
  // ambiguity band); about as good, it is a second answer, and with two the scans cannot tell which
  // is right (MulRan keyframes 2 apart: the wide basin slid 11 m along the road from a right first
  // try, both trusted).
  const QualitySettings& quality = this->quality();
  const auto second_answer = [&](const OdometryStep& again) {
    return std::any_of(answers_.begin(), answers_.end(), [&](const Answer& a) {
      return rivals(again.relative, again.quality.fit_ratio, a.relative, a.fit_ratio, quality);
    });
  };
  // A pose already in dispute (two answers of one registration, far apart, fitting about as well):
  // reaching it again from another start does not tell the two apart. On the campus route in 150 scans
  // (constant velocity, seed 4, step 102) the wide basin from the guess found the right pose and one
  // 1.0 m short of it, ambiguous; the search from no motion then found only the short one, 0.999 m from
  // the right one, just inside the ambiguity tolerance, and it was trusted 1.006 m off.
  const auto lands_on_dispute = [&](const OdometryStep& again) {
    return std::any_of(disputed_.begin(), disputed_.end(),
                       [&](const Eigen::Isometry3d& d) { return !far_apart(again.relative, d, quality); });
  };
  bool ambiguous = false;
  std::vector<Eigen::Isometry3d> tries;
  for (const Eigen::Isometry3d& start : starts)
    if ((wide_basin_ && !searched_) || !start.isApprox(step.guess, 1e-12))  // else tried already
      tries.push_back(start);
  // Where the points above the horizon rest, away from an answer they refuted (first_try): the whole
  // scan registered from there by the local matcher (which holds the reference's model since), as
  // well: the search from there would find the refuted answer again.
  const std::size_t searches = tries.size();
  tries.insert(tries.end(), elsewhere_.begin(), elsewhere_.end());
  // One sample for every start (the first try's: the same seed) and one reference model: the first
  // try's when the recovery matcher builds the same one.
  SampledInput sample;
  if (!tries.empty()) {
    Rng rng(seed);
    sample = sample_input(*sampler_, input, rng);
    const auto model_start = std::chrono::steady_clock::now();
    if (&reference != recovery_reference_ &&
        (&reference != matcher_reference_ || !recovery_->share_reference(*matcher_)))
      recovery_->set_reference(reference);
    recovery_reference_ = &reference;
    seconds += sample.seconds +
               std::chrono::duration<double>(std::chrono::steady_clock::now() - model_start).count();
  }
  for (std::size_t i = 0; i < tries.size(); ++i) {
    Matcher& matcher = i < searches ? *recovery_ : *matcher_;
    PairMatch w = align_sample(matcher, sample, tries[i], quality);
    drop_refuted(w, sample.points);
    settle_rivals(local(reference, matcher), sample, w);
    OdometryStep again = to_step(w, reference, step.guess);
    // An answer that confirms the first registration stands on its own: the sequence check only asked
    // for a second search. One that lands elsewhere must also pass the sequence check. A sound first
    // registration the sequence doubted, found again, is confirmed by the points above the horizon as
    // an unbounded answer is: a search scores the same rings that held the first one.
    const bool elsewhere = far_apart(again.relative, step.first_relative, quality);
    const bool doubted_again = !elsewhere && step.first_trust == Trust::kOk;
    confirm_above_horizon(again, reference, input, sample.points, matcher, doubted_again);
    seconds += again.seconds;
    if (elsewhere) sequence.check(again.quality);
    const bool disputed = again.trusted() && (second_answer(again) || lands_on_dispute(again));
    remember(w, sample.points);
    if (disputed) {
      ambiguous = true;
      consider(again, again.quality.trust);
      continue;
    }
    if (again.trusted()) {
      again.first_trust = step.first_trust;
      again.first_relative = step.first_relative;
      again.recovery = wide_basin_ ? "wide_basin" : "restart";
      again.seconds = seconds;
      step = std::move(again);
      return;
    }
    consider(again, again.quality.trust);
  }
  if (!suspects.empty()) {
    // Nothing trusted, but registrations whose only flaw is their fit: evidence from the scans,
    // where the prior (the guess, the last trusted motion) has none. The scans choose a band of
    // fits, the prior chooses inside it (suspect_choice.hpp). The step stays untrusted.
    std::vector<SuspectCandidate> candidates;
    for (const OdometryStep& s : suspects) candidates.push_back({s.relative, s.quality.fit_ratio});
    const std::size_t chosen = choose_suspect(candidates, input, step.guess, kSuspectFitBand);
    const Trust first = step.first_trust;
    const Eigen::Isometry3d first_relative = step.first_relative;
    step = std::move(suspects[chosen]);
    step.first_trust = first;
    step.first_relative = first_relative;
    step.quality.trust = Trust::kSuspect;
    step.recovery = "least_suspect";
    if (ambiguous)
      step.quality.reason = fmt::format(
          "ambiguous: two answers of this step lie more than {} m or {}° apart and fit about as well",
          quality.ambiguity_metres, quality.ambiguity_degrees);
  } else {
    step.recovery = starts.back().isApprox(step.guess, 1e-12) ? "guess" : "last_motion";
    step.relative = starts.back();
  }
  step.seconds = seconds;
}

void StepWorker::remember(const PairMatch& m, const PointCloud& sample) {
  const RegistrationResult& r = m.result;
  const Trust trust = r.quality.trust;
  const bool only_its_fit = r.converged && (trust == Trust::kOk || trust == Trust::kSuspect);
  if (only_its_fit && !refuted(r.T)) answers_.push_back({r.T, r.quality.fit_ratio});
  if (r.quality.ambiguous) disputed_.push_back(r.T);
  for (const RegistrationResult& other : r.alternatives) {
    const RegistrationQuality q = assess_registration(other, sample, quality());
    if (!q.trusted() || refuted(other.T)) continue;
    answers_.push_back({other.T, q.fit_ratio});
    // The alternatives that make `r` ambiguous are in dispute with it.
    if (r.quality.ambiguous && rivals(r.T, r.quality.fit_ratio, other.T, q.fit_ratio, quality()))
      disputed_.push_back(other.T);
  }
}

Matcher& StepWorker::local(const PointCloud& reference, const Matcher& built) {
  if (&reference != matcher_reference_ && (&built == matcher_.get() || !matcher_->share_reference(built)))
    matcher_->set_reference(reference);
  matcher_reference_ = &reference;
  return *matcher_;
}

void StepWorker::settle_rivals(Matcher& matcher, const SampledInput& sample, PairMatch& m) const {
  if (!m.result.quality.ambiguous) return;
  const QualitySettings& quality = this->quality();
  std::vector<RegistrationResult>& alternatives = m.result.alternatives;
  const std::size_t before = alternatives.size();
  alternatives.erase(std::remove_if(alternatives.begin(), alternatives.end(),
                                    [&](const RegistrationResult& rival) {
                                      if (!far_apart(rival.T, m.result.T, quality)) return false;
                                      const PairMatch again = align_sample(matcher, sample, rival.T, quality);
                                      m.result.seconds += again.result.seconds;
                                      return again.result.converged &&
                                             !far_apart(again.result.T, m.result.T, quality);
                                    }),
                     alternatives.end());
  if (alternatives.size() != before) m.result.quality = assess_registration(m.result, sample.points, quality);
}

bool StepWorker::refuted(const Eigen::Isometry3d& pose) const {
  return std::any_of(refuted_.begin(), refuted_.end(),
                     [&](const Eigen::Isometry3d& r) { return !far_apart(pose, r, quality()); });
}

void StepWorker::drop_refuted(PairMatch& m, const PointCloud& sample) const {
  std::vector<RegistrationResult>& alternatives = m.result.alternatives;
  const auto end = std::remove_if(alternatives.begin(), alternatives.end(),
                                  [&](const RegistrationResult& a) { return refuted(a.T); });
  if (end == alternatives.end()) return;
  alternatives.erase(end, alternatives.end());
  m.result.quality = assess_registration(m.result, sample, quality());
}

void StepWorker::confirm_above_horizon(OdometryStep& step, const PointCloud& reference,
                                       const PointCloud& input, const PointCloud& sample,
                                       const Matcher& built, bool doubted) {
  if (!context_.sensor_frame || !context_.rings || !step.trusted()) return;
  const bool without_translation = answer_without_translation(step.relative, quality());
  if (!without_translation && !context_.unbounded && !doubted) return;
  AboveHorizon said = register_above_horizon(local(reference, built), input, step.relative, quality());
  if (without_translation && !said.telling(step.relative, step.quality.fit_ratio, quality()) && recovery_) {
    if (&reference != recovery_reference_ && !recovery_->share_reference(*matcher_))
      recovery_->set_reference(reference);
    recovery_reference_ = &reference;
    search_above_horizon(said, *recovery_, input, step.relative, quality());
  }
  if (without_translation) {
    check_no_motion_above_horizon(step.quality, step.relative, said, quality());
  } else {
    register_whole_from_there(said, *matcher_, sample, step.relative, quality());
    check_motion_above_horizon(step.quality, step.relative, said, quality());
  }
  step.seconds += said.seconds;
  if (step.trusted()) return;
  refuted_.push_back(step.relative);
  if (const auto there = said.elsewhere(step.relative, quality())) elsewhere_.push_back(*there);
}

OdometryStep StepWorker::to_step(const PairMatch& m, const PointCloud& reference,
                                 const Eigen::Isometry3d& guess) const {
  OdometryStep step;
  step.relative = m.result.T;
  step.guess = guess;
  step.hessian = m.result.H;
  step.converged = m.result.converged;
  step.iterations = m.result.iterations;
  step.score = m.result.score;
  step.matched_points = m.result.matched_points;
  step.reference_points = reference.size();
  step.seconds = m.result.seconds + m.reference_seconds + m.sampling_seconds;
  step.status = to_string(m.result.why);
  step.fallback = m.result.fallback;
  step.quality = m.result.quality;
  // No motion is the answer a lidar's rings always offer: confirmed only by a fit as of one place,
  // where no motion is known yet or the guess says the vehicle moves (sequence_trust.hpp).
  if (context_.rings && (context_.search || far_apart(guess, Eigen::Isometry3d::Identity(), quality())))
    check_unconfirmed_no_motion(step.quality, step.relative, quality());
  check_reachable_motion(step.quality, step.relative, guess, context_.last_turn, context_.reach, quality());
  if (!step.relative.matrix().allFinite()) {  // never chain NaN: keep the guess, say so
    step.relative = guess;
    step.converged = false;
    step.status += " (non-finite result replaced by the guess)";
    step.quality.trust = Trust::kNotConverged;
    step.quality.reason = "non-finite result";
  }
  return step;
}

}  // namespace sextant::odometry_detail
