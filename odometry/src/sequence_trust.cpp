#include "sextant/odometry/sequence_trust.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

namespace sextant {
namespace {

template <typename Field>
double median_of(const std::deque<RegistrationQuality>& window, Field field) {
  std::vector<double> values;
  for (const RegistrationQuality& q : window) values.push_back(field(q));
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

void SequenceTrust::check(RegistrationQuality& quality) const {
  if (!quality.trusted() || trusted_.size() < settings_.min_history) return;
  const double overlap = median_of(trusted_, [](const RegistrationQuality& q) { return q.overlap; });
  const double fit = median_of(trusted_, [](const RegistrationQuality& q) { return q.fit_ratio; });
  if (quality.overlap < settings_.overlap_factor * overlap) {
    quality.trust = Trust::kSuspect;
    quality.reason =
        fmt::format("{:.1f} % of the input matched, below {:.0f} % of the last trusted steps' {:.1f} %",
                    100.0 * quality.overlap, 100.0 * settings_.overlap_factor, 100.0 * overlap);
  } else if (fit > 0.0 && quality.fit_ratio > settings_.fit_factor * fit &&
             quality.fit_ratio > settings_.fit_factor) {
    // Within fit_factor of what a right pose predicts, a fit is that of a right pose, however much
    // better its neighbours fitted (scans that fit better than predicted: the synthetic campus, 0.85).
    quality.trust = Trust::kSuspect;
    quality.reason = fmt::format(
        "fit {:.2f} × the prediction, above {:.1f} × the last trusted steps' {:.2f} and above the "
        "{:.1f} of a right pose",
        quality.fit_ratio, settings_.fit_factor, fit, settings_.fit_factor);
  }
}

void check_unconfirmed_no_motion(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                 const QualitySettings& tolerance, double fit_factor) {
  if (!quality.trusted() || quality.fit_ratio <= fit_factor ||
      far_apart(relative, Eigen::Isometry3d::Identity(), tolerance))
    return;
  quality.trust = Trust::kSuspect;
  quality.reason = fmt::format(
      "no motion (within {} m and {}°) with fit {:.2f} × the prediction, above the {:.1f} of two scans from "
      "one place, where no motion is known yet or the guess moves: a lidar's rings coincide at no motion",
      tolerance.ambiguity_metres, tolerance.ambiguity_degrees, quality.fit_ratio, fit_factor);
}

double reachable_departure(double dt_before, double dt, double max_acceleration) {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  if (!(dt > 0.0 && dt_before > 0.0 && max_acceleration > 0.0)) return kUnknown;
  const double reach = max_acceleration * dt * 0.5 * (dt + dt_before);
  return std::isfinite(reach) ? reach : kUnknown;
}

void check_reachable_motion(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                            const Eigen::Isometry3d& guess, const Eigen::Matrix3d& last_turn, double reach,
                            const QualitySettings& tolerance) {
  const Eigen::Vector3d in_platform = guess.translation();
  const Eigen::Vector3d in_world = last_turn.transpose() * in_platform;
  const double departure =
      std::min((relative.translation() - in_platform).norm(), (relative.translation() - in_world).norm());
  if (!quality.trusted() || !(departure > reach) || departure <= tolerance.ambiguity_metres) return;
  quality.trust = Trust::kSuspect;
  quality.reason = fmt::format(
      "{:.1f} m from the constant-velocity guess (its velocity held in the platform's frame or in the "
      "world), "
      "beyond the {:.1f} m the platform's largest acceleration allows in this step",
      departure, reach);
}

double fit_bar(double max_fit_ratio, std::optional<double> median_fit) {
  return median_fit && *median_fit > 1.0 ? max_fit_ratio * *median_fit : max_fit_ratio;
}

std::optional<double> SequenceTrust::median_fit() const {
  if (trusted_.size() < settings_.min_history) return std::nullopt;
  const double fit = median_of(trusted_, [](const RegistrationQuality& q) { return q.fit_ratio; });
  if (!(fit > 0.0)) return std::nullopt;
  return fit;
}

void SequenceTrust::record(const RegistrationQuality& quality) {
  if (!quality.trusted()) return;
  trusted_.push_back(quality);
  while (trusted_.size() > settings_.window) trusted_.pop_front();
}

}  // namespace sextant
