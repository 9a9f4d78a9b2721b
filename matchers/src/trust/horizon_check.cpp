// Answers confirmed by the points above the horizon (horizon_check.hpp).
#include "sextant/matchers/horizon_check.hpp"

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "sextant/core/units.hpp"

namespace sextant {

PointCloud above_horizon(const PointCloud& scan) {
  std::vector<std::size_t> above;
  const PointsView points = scan.points();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].z() > 0.0f) above.push_back(i);
  return scan.subset(above);
}

namespace {

/// Converged, with overlap and every direction constrained: at most the fit is poor.
bool only_its_fit(const RegistrationQuality& q) {
  return q.trust == Trust::kOk || q.trust == Trust::kSuspect;
}

/// Fits clearly worse than the answer's `answer_fit` (beyond the ambiguity band) and worse than the bar,
/// with no other flaw: at one place every part of a scan fits as the whole does (within the band); where
/// the ground's rings carry the fit, the points above the horizon do not.
bool fits_clearly_worse(const RegistrationQuality& above, double answer_fit,
                        const QualitySettings& tolerance) {
  return only_its_fit(above) && above.fit_ratio > tolerance.max_fit_ratio &&
         above.fit_ratio > tolerance.ambiguity_fit_band * answer_fit;
}

/// How far `T` lies from the answer `relative`, for a reason.
std::string apart(const Eigen::Isometry3d& relative, const Eigen::Isometry3d& T) {
  const Eigen::Isometry3d d = relative.inverse() * T;
  return fmt::format("{:.2f} m and {:.1f}°", d.translation().norm(),
                     Eigen::AngleAxisd(d.linear()).angle() * kDegPerRad);
}

/// The reason of an answer the points above the horizon leave (AboveHorizon::leaves).
std::string moved(const AboveHorizon& above, const Eigen::Isometry3d& relative) {
  return fmt::format("the points above the horizon, registered alone from it, move {}",
                     apart(relative, above.local));
}

/// What the points above the horizon, registered alone from the answer `relative` (whose whole scan fits
/// `answer_fit`), say against it, if anything: they match too little, leave it, or fit clearly worse.
std::optional<std::string> local_objection(const AboveHorizon& above, const Eigen::Isometry3d& relative,
                                           double answer_fit, const QualitySettings& tolerance) {
  const RegistrationQuality& local = above.local_quality;
  if (local.trust == Trust::kLowOverlap)
    return fmt::format("only {:.1f} % of the points above the horizon match there or near it",
                       100.0 * local.overlap);
  if (above.leaves(relative, tolerance)) return moved(above, relative);
  if (fits_clearly_worse(local, answer_fit, tolerance))
    return fmt::format(
        "the points above the horizon fit {:.2f} × the prediction there, clearly worse "
        "than the whole scan's {:.2f}",
        local.fit_ratio, answer_fit);
  return std::nullopt;
}

}  // namespace

bool answer_without_translation(const Eigen::Isometry3d& relative, const QualitySettings& tolerance) {
  return relative.translation().norm() <= tolerance.ambiguity_metres;
}

bool AboveHorizon::telling(const Eigen::Isometry3d& relative, double answer_fit,
                           const QualitySettings& tolerance) const {
  return local_quality.trusted() || local_objection(*this, relative, answer_fit, tolerance).has_value();
}

bool AboveHorizon::leaves(const Eigen::Isometry3d& relative, const QualitySettings& tolerance) const {
  return local_quality.assessed && only_its_fit(local_quality) && far_apart(relative, local, tolerance);
}

std::optional<Eigen::Isometry3d> AboveHorizon::elsewhere(const Eigen::Isometry3d& relative,
                                                         const QualitySettings& tolerance) const {
  if (wide_quality && wide_quality->trusted() && far_apart(relative, wide, tolerance)) return wide;
  if (leaves(relative, tolerance)) return local;
  return std::nullopt;
}

AboveHorizon register_above_horizon(Matcher& local, const PointCloud& input, const Eigen::Isometry3d& answer,
                                    const QualitySettings& tolerance) {
  AboveHorizon said;
  const PointCloud above = above_horizon(input);
  if (above.empty()) return said;
  const RegistrationResult alone = local.align(above, answer);
  said.local = alone.T;
  said.local_quality = assess_registration(alone, above, tolerance);
  said.seconds = alone.seconds;
  return said;
}

void search_above_horizon(AboveHorizon& said, Matcher& wide, const PointCloud& input,
                          const Eigen::Isometry3d& answer, const QualitySettings& tolerance) {
  const PointCloud above = above_horizon(input);
  if (above.empty()) return;
  const RegistrationResult searched = wide.align(above, answer);
  said.wide = searched.T;
  said.wide_quality = assess_registration(searched, above, tolerance);
  said.seconds += searched.seconds;
}

void check_no_motion_above_horizon(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                   const AboveHorizon& above, const QualitySettings& tolerance) {
  if (!quality.trusted() || !answer_without_translation(relative, tolerance) || !above.local_quality.assessed)
    return;
  const auto suspect = [&](const std::string& what) {
    quality.trust = Trust::kSuspect;
    quality.reason = fmt::format(
        "no translation (within {} m), but {}: a lidar's ground rings coincide at no translation "
        "whatever the vehicle did",
        tolerance.ambiguity_metres, what);
  };
  if (const auto objection = local_objection(above, relative, quality.fit_ratio, tolerance))
    return suspect(*objection);
  if (above.wide_quality && above.wide_quality->trusted() && far_apart(relative, above.wide, tolerance))
    suspect(fmt::format("the points above the horizon, searched for alone, lie {} away",
                        apart(relative, above.wide)));
}

void register_whole_from_there(AboveHorizon& said, Matcher& local, const PointCloud& sample,
                               const Eigen::Isometry3d& relative, const QualitySettings& tolerance) {
  if (!said.leaves(relative, tolerance)) return;
  const RegistrationResult from_there = local.align(sample, said.local);
  said.seconds += from_there.seconds;
  if (from_there.converged) said.whole = from_there.T;
}

void check_motion_above_horizon(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                const AboveHorizon& above, const QualitySettings& tolerance) {
  if (!quality.trusted() || !above.leaves(relative, tolerance) || !above.whole ||
      !far_apart(relative, *above.whole, tolerance))
    return;
  quality.trust = Trust::kSuspect;
  quality.reason = fmt::format(
      "{}, and the whole scan registered from there ends {} away; nothing else bounds this answer: at a "
      "right one every part of a scan rests where the whole does",
      moved(above, relative), apart(relative, *above.whole));
}

}  // namespace sextant
