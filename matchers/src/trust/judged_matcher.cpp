// Every matcher's poses judged on the default ML-NDT's last layer (judged_matcher.hpp).
#include "sextant/matchers/judged_matcher.hpp"

#include "ndt/ndt_score.hpp"

#include <utility>

#include "sextant/matchers/matcher_traits.hpp"

namespace sextant {
namespace {

/// The default ML-NDT's layers alone: its precision stage only refines, and the checks read the last
/// layer.
MlndtSettings judge_settings() {
  MlndtSettings s;
  s.precision.min_cell = 0.0;  // off
  return s;
}

}  // namespace

JudgedMatcher::JudgedMatcher(std::unique_ptr<Matcher> matcher)
    : matcher_(std::move(matcher)), judge_(judge_settings()) {}

void JudgedMatcher::set_reference(const PointCloud& reference) {
  matcher_->set_reference(reference);
  judge_.set_reference(reference);
}

RegistrationResult JudgedMatcher::align(const PointCloud& input, const Eigen::Isometry3d& initial) {
  RegistrationResult r = matcher_->align(input, initial);
  if (judge_.layers().empty() || judge_.layers().back().empty()) return r;  // nothing to judge with
  const ScoreEvaluation at = judge_.last_layer_at(input, r.T);
  r.matched_points = at.matched;
  r.mean_matched_score = at.matched > 0 ? at.matched_score / static_cast<double>(at.matched) : 0.0;
  r.predicted_matched_score = judge_.predicted_matched_score();
  r.constraint_hessian = at.hessian;
  return r;
}

std::unique_ptr<Matcher> judged(std::unique_ptr<Matcher> matcher) {
  if (!matcher || matcher_traits(matcher->name()).judges_itself) return matcher;
  return std::make_unique<JudgedMatcher>(std::move(matcher));
}

}  // namespace sextant
