#include "sextant/matchers/register_pair.hpp"

#include <limits>
#include <memory>
#include <utility>

#include <Eigen/Cholesky>

#include "sextant/core/rng.hpp"
#include "sextant/matchers/horizon_check.hpp"

namespace sextant {

namespace {

/// register_pair about the origin of the clouds' coordinates; `used` becomes the matcher of the result,
/// which holds the reference's model.
PairRegistration register_about_origin(const PointCloud& reference, const PointCloud& input,
                                       const PairRegistrationRequest& request,
                                       std::unique_ptr<Matcher>& used) {
  PairRegistration out;
  const auto sampler = request.sampler();
  const Eigen::Isometry3d initial = request.init.value_or(Eigen::Isometry3d::Identity());
  const MatcherFactory& wide = request.matcher.make_wide;
  const bool own_wide_basin = request.matcher.own_wide_basin;
  out.searched_without_guess = !request.init && request.wide_basin && wide;
  auto matcher = out.searched_without_guess ? wide() : request.matcher.make();
  Rng rng(request.seed);
  out.match = match_pair(*matcher, *sampler, reference, input, initial, rng);
  out.searched = own_wide_basin || out.searched_without_guess;
  out.search = out.searched ? "wide basin" : "from the guess";
  used = std::move(matcher);
  if (out.match.result.quality.trusted() || out.searched || !request.wide_basin || !wide) return out;
  auto wide_matcher = wide();
  Rng again(request.seed);  // the same sample
  PairMatch retry = match_pair(*wide_matcher, *sampler, reference, input, initial, again);
  const std::string first = to_string(out.match.result.quality.trust);
  if (retry.result.quality.trusted()) {
    out.match = std::move(retry);
    used = std::move(wide_matcher);
    out.searched = true;
    out.search += ", " + first + ": recovered by the wide basin";
  } else {
    out.search += ", " + first + ": the wide basin found no trusted pose either";
  }
  return out;
}

/// A trusted answer, for clouds in their sensor's frame, confirmed by the input's points above the
/// horizon (horizon_check.hpp): registered alone from it by the matcher, with the reference model of
/// `built` (which registered it); for an answer without translation searched for with the wide basin
/// where that tells nothing (not with `wide_basin` off). Nothing else bounds a pair's answer.
void confirm_above_horizon(PairRegistration& out, const PointCloud& reference, const PointCloud& input,
                           const PairRegistrationRequest& request, const Matcher& built) {
  RegistrationResult& r = out.match.result;
  const QualitySettings quality;
  if (!r.quality.trusted()) return;
  const auto local = request.matcher.make();
  if (!local->share_reference(built)) local->set_reference(reference);
  AboveHorizon said = register_above_horizon(*local, input, r.T, quality);
  if (!answer_without_translation(r.T, quality)) {
    if (said.leaves(r.T, quality)) {  // only then is the registration's sample needed again
      const auto sampler = request.sampler();
      Rng rng(request.seed);
      register_whole_from_there(said, *local, sample_input(*sampler, input, rng).points, r.T, quality);
    }
    check_motion_above_horizon(r.quality, r.T, said, quality);
  } else {
    if (!said.telling(r.T, r.quality.fit_ratio, quality) && request.wide_basin && request.matcher.make_wide) {
      const auto wide = request.matcher.make_wide();
      if (!wide->share_reference(*local)) wide->set_reference(reference);
      search_above_horizon(said, *wide, input, r.T, quality);
    }
    check_no_motion_above_horizon(r.quality, r.T, said, quality);
  }
  r.seconds += said.seconds;
}

}  // namespace

PairRegistration register_pair(const PointCloud& reference, const PointCloud& input,
                               const PairRegistrationRequest& request) {
  const CentredFrame frame(registration_centre(reference));
  std::unique_ptr<Matcher> used;
  if (!frame.moved()) {
    PairRegistration out = register_about_origin(reference, input, request, used);
    out.sensor = resolve_sensor(request.sensor, input);
    if (out.sensor->kind == SensorKind::spinning)
      confirm_above_horizon(out, reference, input, request, *used);
    return out;
  }
  PairRegistrationRequest local = request;
  if (request.init) local.init = frame.local(*request.init);
  PairRegistration out = register_about_origin(frame.cloud(reference), frame.cloud(input), local, used);
  out.centre = frame.centre();
  RegistrationResult& r = out.match.result;
  r.T = frame.coordinates(r.T);
  for (RegistrationResult& alternative : r.alternatives) {
    alternative.T = frame.coordinates(alternative.T);
    if (alternative.before_precision)
      alternative.before_precision = frame.coordinates(*alternative.before_precision);
  }
  if (r.before_precision) r.before_precision = frame.coordinates(*r.before_precision);
  return out;
}

Matrix6d registration_covariance(const Matrix6d& H) {
  const Eigen::LLT<Matrix6d> llt(H);
  if (!H.allFinite() || llt.info() != Eigen::Success)
    return Matrix6d::Constant(std::numeric_limits<double>::quiet_NaN());
  return llt.solve(Matrix6d::Identity());
}

}  // namespace sextant
