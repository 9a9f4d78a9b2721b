#pragma once
// The trust of a registration against its own sequence (issue 22). Consecutive scans of one lidar
// on one vehicle overlap about as much from one step to the next, and their matched points fit the
// reference's Gaussians about as well. A step whose overlap falls well below, or whose fit rises
// well above, the median of the last trusted steps slid or jumped, even when each number alone
// would pass (registration_quality.hpp's absolute checks). The window holds the trusted steps:
// after recovery where one step's guess needs the last (constant velocity, local map); the steps
// trusted at their first registration where the steps are independent (the odometry guess), whose
// recoveries then run in parallel.
#include <cstddef>
#include <deque>
#include <optional>

#include <Eigen/Geometry>

#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

struct SequenceTrustSettings {
  std::size_t window = 10;      ///< trusted steps the medians are taken over [count]
  std::size_t min_history = 3;  ///< no relative check before this many trusted steps [count]
  double overlap_factor = 0.9;  ///< suspect below this × the median overlap [ratio]
  /// suspect above this × the median fit ratio, when also above this × a right pose's prediction [ratio]
  double fit_factor = 1.1;
};

class SequenceTrust {
 public:
  explicit SequenceTrust(SequenceTrustSettings settings = {}) : settings_(settings) {}
  /// Marks a trusted `quality` suspect (with the reason) when it falls out of the sequence's range: an
  /// overlap below overlap_factor × the window's median, or a fit above fit_factor × its median that is
  /// also above fit_factor × the prediction (a fit within it is a right pose's, the window's no matter).
  void check(RegistrationQuality& quality) const;
  /// Adds a trusted step to the window (untrusted ones are ignored).
  void record(const RegistrationQuality& quality);
  /// The median fit ratio of the window's trusted steps, from min_history of them on (none before, and
  /// for a matcher that predicts no fit).
  std::optional<double> median_fit() const;

 private:
  SequenceTrustSettings settings_;
  std::deque<RegistrationQuality> trusted_;
};

/// The absolute fit check's bar (QualitySettings::max_fit_ratio) for a step of a sequence whose trusted
/// steps fit `median_fit` × the prediction: `max_fit_ratio` × that median where it is above 1, else
/// `max_fit_ratio` itself. The bar was set on spinning lidars, where right poses fit about as predicted
/// and poses that slid clearly worse; a sensor whose right poses fit worse than predicted (a sparse
/// solid-state scan, whose cells estimate their Gaussians from a few points) keeps that separation in its
/// own units. Never lowered: a scene that fits better than predicted keeps the bar of a right pose. The
/// odometry applies it only to the sensors the bar was not measured on (solid-state ones): raised for a
/// spinning lidar it lets far alternatives pass and makes right steps ambiguous (docs/odometry.md,
/// "Which check applies to which sensor and platform").
double fit_bar(double max_fit_ratio, std::optional<double> median_fit);

/// For a step with no motion known yet (the constant-velocity guess knows none, and the registration
/// searches from no motion) or whose guess moves (StepWorker applies it there), marks a trusted
/// `quality` suspect when its `relative` lies within `tolerance`'s ambiguity distance of no motion but
/// fits worse than two scans from one place do: above `fit_factor` × the prediction (the sequence check's own
/// "about equal"). A lidar's rings coincide at no motion whatever the vehicle did, so there the scans always
/// offer an answer, which can pass the absolute checks and leave the chain standing still on a map of
/// scans stacked at one place; two scans from one place fit about as predicted (docs/matcher_defaults.md,
/// "The collapse to no motion, and the check that stops it").
void check_unconfirmed_no_motion(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                 const QualitySettings& tolerance,
                                 double fit_factor = SequenceTrustSettings{}.fit_factor);

/// How far a platform accelerating at most `max_acceleration` can depart from the constant-velocity
/// prediction of a step of `dt` seconds, the velocity measured over the step before, of `dt_before`
/// seconds: their mid-times lie (dt + dt_before) / 2 apart, so the velocity changes by at most a·(dt +
/// dt_before) / 2 and the step's motion by dt times that [m]. ∞ when a time is unknown or not positive,
/// or `max_acceleration` is 0.
double reachable_departure(double dt_before, double dt, double max_acceleration);

/// Marks a trusted `quality` suspect when `relative` lies farther than `reach` (reachable_departure) and
/// than `tolerance`'s ambiguity distance from both translations a constant velocity predicts: `guess`'s,
/// the last motion scaled to this step (the velocity constant in the platform's frame: a car's turns
/// carry it along), and the same velocity held in the world, `guess`'s translation turned back by
/// `last_turn`, the rotation of that last motion (step k's displacement in scan k − 1's frame is
/// R_{k−1}ᵀ v Δt_k, step k − 1's in scan k − 2's R_{k−2}ᵀ v Δt_{k−1}, so a constant v turns it by
/// (R_{k−2}ᵀ R_{k−1})ᵀ): a lidar that turns back and forth while its platform holds its course, whose
/// velocity reverses its direction in the sensor's frame with no acceleration at all
/// (docs/matcher_defaults.md, "A sensor that turns on its own"). The platform could not have made a
/// motion far from both, however well it fits, as a wide-basin answer behind the last scan inside a
/// local map can (docs/matcher_defaults.md, "A motion no platform makes").
void check_reachable_motion(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                            const Eigen::Isometry3d& guess, const Eigen::Matrix3d& last_turn, double reach,
                            const QualitySettings& tolerance);

}  // namespace sextant
