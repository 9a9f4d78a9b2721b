#include "sextant/posegraph/loop_closure.hpp"

#include <cmath>
#include <limits>

#include "sextant/core/units.hpp"
#include "sextant/posegraph/relative_pose_factor.hpp"

namespace sextant {
bool LoopClosureSettings::valid(std::string* why) const {
  const auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(radius > 0.0) || !std::isfinite(radius)) return fail("radius must be a positive number [m]");
  if (min_index_gap < 1) return fail("min_index_gap must be ≥ 1");
  if (!(min_path_gap >= 0.0) || !std::isfinite(min_path_gap)) return fail("min_path_gap must be ≥ 0 [m]");
  if (stride < 1) return fail("stride must be ≥ 1");
  if (!(max_mean_score > 0.0)) return fail("max_mean_score must be positive");
  if (!(min_matched_fraction >= 0.0 && min_matched_fraction <= 1.0))
    return fail("min_matched_fraction must be in [0, 1]");
  if (!(max_correction_m > 0.0) || !(max_correction_deg > 0.0))
    return fail("max_correction_m and max_correction_deg must be positive");
  if (!(information_scale > 0.0) || !std::isfinite(information_scale))
    return fail("information_scale must be a positive number");
  return true;
}

std::vector<LoopClosureCandidate> find_loop_closure_candidates(const std::vector<Eigen::Isometry3d>& poses,
                                                               const LoopClosureSettings& settings) {
  std::vector<double> path(poses.size(), 0.0);
  for (std::size_t k = 1; k < poses.size(); ++k)
    path[k] = path[k - 1] + (poses[k].translation() - poses[k - 1].translation()).norm();
  std::vector<LoopClosureCandidate> out;
  for (std::size_t j = settings.min_index_gap; j < poses.size(); ++j) {
    if (!out.empty() && j < out.back().j + settings.stride) continue;
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_i = 0;
    for (std::size_t i = 0; i + settings.min_index_gap <= j; ++i) {
      if (path[j] - path[i] < settings.min_path_gap) continue;
      const double d = (poses[j].translation() - poses[i].translation()).norm();
      if (d <= settings.radius && d < best) {
        best = d;
        best_i = i;
      }
    }
    if (std::isfinite(best)) out.push_back({best_i, j, best, relative(poses[best_i], poses[j])});
  }
  return out;
}

LoopClosureDecision judge_loop_closure(const RegistrationResult& r, const LoopClosureCandidate& candidate,
                                       const LoopClosureSettings& settings) {
  LoopClosureDecision d;
  d.mean_score = r.matched_points ? r.score / static_cast<double>(r.matched_points)
                                  : std::numeric_limits<double>::infinity();
  d.matched_fraction =
      r.input_points ? static_cast<double>(r.matched_points) / static_cast<double>(r.input_points) : 0.0;
  const Eigen::Isometry3d correction = relative(candidate.guess, r.T);
  d.correction_m = translation_norm(correction);
  d.correction_deg = rotation_angle(correction) * kDegPerRad;
  if (!r.converged) {
    d.rejection = ClosureRejection::not_converged;
    d.reason = "did not converge (" + to_string(r.why) + ")";
  } else if (!(d.mean_score <= settings.max_mean_score)) {
    d.rejection = ClosureRejection::score;
    d.reason = "mean score per point above " + std::to_string(settings.max_mean_score);
  } else if (d.matched_fraction < settings.min_matched_fraction) {
    d.rejection = ClosureRejection::matched_fraction;
    d.reason = "matched fraction below " + std::to_string(settings.min_matched_fraction);
  } else if (d.correction_m > settings.max_correction_m || d.correction_deg > settings.max_correction_deg) {
    d.rejection = ClosureRejection::correction;
    d.reason = "correction of the guess too large";
  } else if (settings.require_trust && !r.quality.trusted()) {
    d.rejection = ClosureRejection::untrusted;
    d.reason = "not trusted (" + (r.quality.assessed ? r.quality.reason : std::string("not assessed")) + ")";
  }
  if (!d.reason.empty()) return d;
  d.information = settings.information_scale * information_from_pose6_hessian(r.H, r.T);
  Matrix6d L;
  if (!sqrt_information(d.information, &L)) {
    d.rejection = ClosureRejection::hessian;
    d.reason = "Hessian not positive definite";
    d.information.setZero();
    return d;
  }
  d.accepted = true;
  return d;
}

}  // namespace sextant
