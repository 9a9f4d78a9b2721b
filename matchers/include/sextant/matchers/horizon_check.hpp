#pragma once
// An answer without translation, and one that nothing else bounds, confirmed by the points above the
// horizon (issue 22). A spinning lidar's ground rings are circles about the sensor, so two scans' rings
// coincide at no translation (and at any turn about the vertical) whatever the vehicle did, and where
// they are most of a sparse scan they hold a registration there, fitting as a real stop fits
// (docs/matcher_defaults.md, "The ground's rings hold a sparse scan"). The points above a level sensor's
// horizon hold no ground ring: at a stop they rest where the rest of the scan does, and after a drive
// they leave. The rings also hold a registration short of the motion: an answer with translation that
// nothing else bounds (a pair; an odometry step with no trusted velocity before it) must rest where
// those points rest too.
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
/// as the whole does, and where the ground's rings carry the fit the rest does not
/// (docs/matcher_defaults.md, "Pairs far apart, from the identity"); or the wide basin's search for them
/// ends that far away, trusted. When they tell nothing (degenerate, not converged, not assessed) the
/// answer stands.
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
/// rests where the whole does, and the whole scan returns to it from nearby, also where walls hold the
/// points above the horizon only weakly along a street. Only this objection: away from no translation
/// those points may fit worse than the whole and match less on right answers (docs/matcher_defaults.md,
/// "Short of the motion, with nothing to bound it").
void check_motion_above_horizon(RegistrationQuality& quality, const Eigen::Isometry3d& relative,
                                const AboveHorizon& above, const QualitySettings& tolerance);

}  // namespace sextant
