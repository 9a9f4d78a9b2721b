#include "sextant/matchers/register_pair.hpp"

#include <limits>
#include <utility>

#include <Eigen/Cholesky>

#include "sextant/core/rng.hpp"

namespace sextant {

namespace {

/// register_pair about the origin of the clouds' coordinates.
PairRegistration register_about_origin(const PointCloud& reference, const PointCloud& input,
                                       const PairRegistrationRequest& request) {
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
  if (out.match.result.quality.trusted() || out.searched || !request.wide_basin || !wide) return out;
  const auto wide_matcher = wide();
  Rng again(request.seed);  // the same sample
  PairMatch retry = match_pair(*wide_matcher, *sampler, reference, input, initial, again);
  const std::string first = to_string(out.match.result.quality.trust);
  if (retry.result.quality.trusted()) {
    out.match = std::move(retry);
    out.searched = true;
    out.search += ", " + first + ": recovered by the wide basin";
  } else {
    out.search += ", " + first + ": the wide basin found no trusted pose either";
  }
  return out;
}

/// `cloud` with every point moved by −`centre`.
PointCloud about(const PointCloud& cloud, const Eigen::Vector3d& centre) {
  return cloud.transformed(Eigen::Isometry3d(Eigen::Translation3d(-centre)));
}

}  // namespace

Eigen::Vector3d registration_centre(const PointCloud& reference) {
  if (reference.empty()) return Eigen::Vector3d::Zero();
  const Bounds box = reference.bounds();
  const Eigen::Vector3d low = box.min.cast<double>(), high = box.max.cast<double>();
  const Eigen::Vector3d outside =
      low.cwiseMax(Eigen::Vector3d::Zero()) - high.cwiseMin(Eigen::Vector3d::Zero());
  if (!(outside.norm() > 0.5 * (high - low).norm())) return Eigen::Vector3d::Zero();
  return 0.5 * (low + high);
}

PairRegistration register_pair(const PointCloud& reference, const PointCloud& input,
                               const PairRegistrationRequest& request) {
  const Eigen::Vector3d centre = registration_centre(reference);
  if (centre.isZero()) return register_about_origin(reference, input, request);
  const Eigen::Isometry3d to_file(Eigen::Translation3d{centre}), to_local = to_file.inverse();
  PairRegistrationRequest local = request;
  if (request.init) local.init = to_local * *request.init * to_file;
  PairRegistration out = register_about_origin(about(reference, centre), about(input, centre), local);
  out.centre = centre;
  RegistrationResult& r = out.match.result;
  r.T = to_file * r.T * to_local;
  for (RegistrationResult& alternative : r.alternatives) alternative.T = to_file * alternative.T * to_local;
  return out;
}

Matrix6d registration_covariance(const Matrix6d& H) {
  const Eigen::LLT<Matrix6d> llt(H);
  if (!H.allFinite() || llt.info() != Eigen::Success)
    return Matrix6d::Constant(std::numeric_limits<double>::quiet_NaN());
  return llt.solve(Matrix6d::Identity());
}

}  // namespace sextant
