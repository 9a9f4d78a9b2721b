#include "sextant/eval/registration_metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "sextant/core/io/uos.hpp"
#include "sextant/core/units.hpp"

namespace sextant {

namespace {

constexpr double kCmPerMetre = 100.0;

RegistrationError non_finite_error() {
  RegistrationError e;
  e.parameters.fill(kNaN);
  e.translation_cm = kNaN;
  e.rotation_deg = kNaN;
  e.finite = false;
  return e;
}

}  // namespace

const std::array<std::string, 6>& parameter_names() {
  static const std::array<std::string, 6> names{"tx", "ty", "tz", "α", "β", "γ"};
  return names;
}

// The axis map lives in core's uos I/O (which works in cm); keep metres here.
Eigen::Isometry3d to_uos_axes(const Eigen::Isometry3d& T) {
  Eigen::Matrix4d M = internal_pose_to_uos(T);
  M.topRightCorner<3, 1>() /= kCmPerMetre;
  return Eigen::Isometry3d(M);
}

Eigen::Vector3d to_uos_axes(const Eigen::Vector3d& v) {
  return internal_to_uos(v) / kCmPerMetre;
}

RegistrationError registration_error(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& ground_truth,
                                     AxisConvention axes) {
  if (!is_finite(estimate) || !is_finite(ground_truth)) return non_finite_error();
  Eigen::Isometry3d E = relative(ground_truth, estimate);  // E = T_gt⁻¹ · T_est
  RegistrationError e;
  e.translation_cm = translation_norm(E) * kCmPerMetre;
  e.rotation_deg = rotation_angle(E) * kDegPerRad;
  if (axes == AxisConvention::uos) E = to_uos_axes(E);
  const Pose6 p = to_pose6(E);  // eq. (3.8) angles
  e.parameters = {p.x * kCmPerMetre,    p.y * kCmPerMetre,   p.z * kCmPerMetre,
                  p.alpha * kDegPerRad, p.beta * kDegPerRad, p.gamma * kDegPerRad};
  return e;
}

bool SuccessCriterion::valid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!(max_translation_cm > 0.0)) return fail("max_translation_cm must be > 0");
  if (!(max_rotation_deg > 0.0)) return fail("max_rotation_deg must be > 0");
  return true;
}

bool SuccessCriterion::succeeded(const RegistrationError& error, bool converged) const {
  if (!error.finite) return false;
  if (require_converged && !converged) return false;
  return error.translation_cm < max_translation_cm && error.rotation_deg < max_rotation_deg;
}

SuccessCriterion thesis_success_criterion(const std::string& name) {
  SuccessCriterion c;
  if (name == "translation_50cm") return c;
  if (name == "translation_200cm_rotation_10deg") {
    c.max_translation_cm = 200.0;
    c.max_rotation_deg = 10.0;
    return c;
  }
  throw std::invalid_argument("unknown success criterion '" + name +
                              "' (known: translation_50cm, translation_200cm_rotation_10deg)");
}

bool RegistrationStatsSettings::valid(std::string* why) const {
  return success.valid(why);
}

RegistrationStats registration_stats(const std::vector<RegistrationSample>& samples,
                                     const RegistrationStatsSettings& settings) {
  RegistrationStats stats;
  stats.count = samples.size();
  std::array<std::vector<double>, 6> params;
  std::vector<double> trans, rot, iterations, seconds, matched;
  for (const RegistrationSample& s : samples) {
    const RegistrationError e = registration_error(s.estimate, s.ground_truth, settings.axes);
    const bool ok = settings.success.succeeded(e, s.converged);
    stats.errors.push_back(e);
    stats.success.push_back(ok);
    if (ok) ++stats.successes;
    iterations.push_back(s.iterations);
    seconds.push_back(s.seconds);
    if (s.total_points > 0)
      matched.push_back(100.0 * static_cast<double>(s.matched_points) / static_cast<double>(s.total_points));
    if (settings.errors_of_successes_only && !ok) continue;
    for (int k = 0; k < 6; ++k) params[k].push_back(e.parameters[k]);
    trans.push_back(e.translation_cm);
    rot.push_back(e.rotation_deg);
  }
  stats.success_rate =
      stats.count ? static_cast<double>(stats.successes) / static_cast<double>(stats.count) : 0.0;
  for (int k = 0; k < 6; ++k) stats.parameters[k] = summarize(params[k]);
  stats.translation_cm = summarize(trans);
  stats.rotation_deg = summarize(rot);
  stats.iterations = summarize(iterations);
  stats.seconds = summarize(seconds);
  stats.matched_percent = summarize(matched);
  return stats;
}

}  // namespace sextant
