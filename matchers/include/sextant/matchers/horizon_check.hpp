#pragma once
// An answer without translation, and one that nothing else bounds, confirmed by the points above the
// horizon (issue 22). A spinning lidar's ground rings are circles about the sensor, so two scans' rings
// coincide at no translation (and at any turn about the vertical) whatever the vehicle did, and where
// they are most of a sparse scan they hold a registration there: MulRan 0–107 read as 16 rings stood still
// for five keyframes while the car moved 1.4–4.7 m each, fitting 0.94–1.12 × the prediction, as a real stop
// fits, and `sextant match` trusted 16-ring pairs 2–5 m apart at no translation (docs/matcher_defaults.md,
// "The ground's rings hold a sparse scan"). The points above a level sensor's horizon hold no ground ring: at
// a stop they rest where the rest of the scan does, and after a drive they leave. The rings also hold a
// registration short of the motion: an answer with translation that nothing else bounds (a pair; an odometry
// step with no trusted velocity before it) must rest where those points rest too.
//
//   if (r.quality.trusted() && answer_without_translation(r.T, quality)) {
//     AboveHorizon said = register_above_horizon(*local, input, r.T, quality);
//     if (!said.telling(r.T, r.quality.fit_ratio, quality))
//       search_above_horizon(said, *wide, input, r.T, quality);
//     check_no_motion_above_horizon(r.quality, r.T, said, quality);
//   }
#include <optional>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/registration_quality.hpp"

namespace sextant {

/// The points of `scan`, in its sensor's frame, above the sensor's horizon (z > 0).
PointCloud above_horizon(const PointCloud& scan);

/// Whether `relative` lies within `tolerance`'s ambiguity distance of no translation (any rotation).
bool answer_without_translation(const Eigen::Isometry3d& relative, const QualitySettings& tolerance);

/// What the points above the horizon say about an answer: their registration alone from it, and,
/// where that one tells nothing (telling()), the wide basin's search for them from it.
struct AboveHorizon {
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  RegistrationQuality local_quality;
  Eigen::Isometry3d wide = Eigen::Isometry3d::Identity();
  std::optional<RegistrationQuality> wide_quality;  ///< none: not searched
  /// Where the whole scan, registered from where they rest when they leave an answer that moves, ends
  /// (converged); none: not registered (register_whole_from_there)
  std::optional<Eigen::Isometry3d> whole;
  double seconds = 0.0;  ///< the registrations' time
  /// Whether the local registration decides for the answer `relative`, whose whole scan fits
  /// `answer_fit` × the prediction: it matches too little, is trusted, leaves the answer (farther than
  /// `tolerance`) with at most a poor fit, or stays and fits clearly worse than the whole scan
  /// (check_no_motion_above_horizon).
  bool telling(const Eigen::Isometry3d& relative, double answer_fit, const QualitySettings& tolerance) const;
  /// Whether their registration alone from the answer `relative` leaves it: assessed, converged, with
  /// overlap and every direction constrained, farther than `tolerance`.
  bool leaves(const Eigen::Isometry3d& relative, const QualitySettings& tolerance) const;
  /// Where they rest away from the answer `relative` (farther than `tolerance`), if they say so: the wide
  /// basin's search for them, trusted; else their local registration, converged with overlap and every
  /// direction constrained. A start for another registration of the whole scan.
  std::optional<Eigen::Isometry3d> elsewhere(const Eigen::Isometry3d& relative,
                                             const QualitySettings& tolerance) const;
};

/// The points of `input` (in its sensor's frame) above the horizon registered alone from `answer` by
/// `local`, which holds the reference's model. Not assessed (local_quality.assessed false) when no
/// point of `input` lies above the horizon.
AboveHorizon register_above_horizon(Matcher& local, const PointCloud& input, const Eigen::Isometry3d& answer,
                                    const QualitySettings& tolerance);

/// Where that registration tells nothing (AboveHorizon::telling), the wide basin's search for the same
/// points from `answer`, by `wide`, which holds the reference's model.
void search_above_horizon(AboveHorizon& said, Matcher& wide, const PointCloud& input,
                          const Eigen::Isometry3d& answer, const QualitySettings& tolerance);

/// For an answer without translation (answer_without_translation): marks a trusted `quality` suspect
/// when the scan's points above the horizon do not confirm it. They match too little there (the local
/// registration is low_overlap); or their registration from it leaves it, farther than the tolerance,
/// converged, with overlap and every direction constrained: the answer is not where the world's points
/// rest, whatever their fit; or they stay but fit clearly worse than the whole scan (beyond
/// ambiguity_fit_band × its fit) and worse than max_fit_ratio: at one place every part of a scan fits
/// as the whole does, and where the ground's rings carry the fit the rest does not (MulRan keyframes
/// 148 → 151, 19 m apart along a riverside road, from the identity: the whole fits 1.29 at no translation,
/// better than at the reference's pose, the points above the horizon 1.58; right answers and stops
/// measured 0.97–1.09 × the whole); or the wide basin's search for them ends that far away, trusted.
/// When they tell nothing (degenerate, not converged, not assessed) the answer stands.
void check_no_motion_above_horizon(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                   const AboveHorizon& above, const QualitySettings& tolerance);

/// Where the points above the horizon leave the answer `relative` (AboveHorizon::leaves), the whole scan's
/// `sample` registered from where they rest by `local`, which holds the reference's model:
/// AboveHorizon::whole.
void register_whole_from_there(AboveHorizon& said, Matcher& local, const PointCloud& sample,
                               const Eigen::Isometry3d& relative, const QualitySettings& tolerance);

/// For an answer with translation that nothing else bounds: marks a trusted `quality` suspect when the
/// scan's points above the horizon, registered alone from it, leave it (farther than the tolerance,
/// converged, with overlap and every direction constrained) and the whole scan, registered from where they
/// rest, does not come back to it (register_whole_from_there): at a right answer every part of a scan
/// rests where the whole does, and the whole scan returns to it from nearby. MulRan keyframes 13 → 14 as
/// 16 rings, the first step of `sextant odometry` (no motion known): the registration ended 2.37 m on
/// where the car moved 4.0 m, fitting 1.21 × the prediction, trusted; its points above the horizon move
/// 1.65 m on from it, to 0.17 m from the reference, and the whole scan from there ends at 4.09 m. On the
/// synthetic campus read every 9 m, the points above the horizon of right answers at a turn or along a
/// street moved 1.10–1.33 m (walls that hold them weakly along the street), and the whole scan came back.
/// Only this objection: away from no translation those points may fit worse than the whole and match less
/// (measured 1.30–1.45 × the prediction on right steps whose whole scan fits 1.08–1.30).
void check_motion_above_horizon(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                const AboveHorizon& above, const QualitySettings& tolerance);

}  // namespace sextant
