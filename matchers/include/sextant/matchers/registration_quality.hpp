#pragma once
// Whether to believe a registration (issue 22). `converged` is a statement about the optimiser: the
// step became small. It says nothing about whether the pose is right: a registration that slid 5 m
// along a road, or matched 100 of 6,000 points, converges as well. The quality assessment looks at
// the solution itself:
//
//   overlap     — matched input points (in a Gaussian and within the truncation τ of the last
//                 layer, or within the ICP distance) / input points. A wrong pose puts most points
//                 where the reference has no surface.
//   degeneracy  — the Hessian of the score at the solution (R = H⁻¹, eq. 3.50), rotations scaled to
//                 metres at the input's RMS range L (H' = S·H·S, S = diag(1, 1, 1, 1/L, 1/L, 1/L)):
//                 the weakest direction's eigenvalue over the strongest. A direction the scene leaves
//                 unconstrained (a corridor, a road between two walls) has a near-zero eigenvalue: the
//                 pose along it is a guess, whatever the optimiser says.
//   fit         — the mean score of a matched point over what the Gaussians predict for a right pose:
//                 for the Mahalanobis score (eq. 3.11) each matched term is eᵀC⁻¹e of a point drawn
//                 from its cell's N(μ, C), a χ² variable with 3 degrees of freedom (mean 3).
//
//   trust:  ok          — converged, and every check passes
//           not_converged — the optimiser did not converge (result.why says why)
//           degenerate  — weakest / strongest constraint below min_constraint_ratio
//           low_overlap — overlap below min_overlap
//           suspect     — the fit is worse than max_fit_ratio × the prediction, or the result is
//                         ambiguous: another solution the matcher reached (result.alternatives)
//                         passes the same checks, fits about as well (ambiguity_fit_band) and lies
//                         more than ambiguity_metres or ambiguity_degrees away. Two poses that far apart
//                         cannot both be right, and the checks cannot tell which is
//                         (docs/matcher_defaults.md, "Two answers are no answer").
#include <string>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

struct QualitySettings {
  /// Below this fraction of the input matched, a registration is low_overlap: consecutive scans of a
  /// moving lidar share most of their view, a wrong pose puts most points where the reference has no
  /// surface; noisy indoor scans can fall below it although right (docs/matcher_defaults.md, "The
  /// thresholds' measured ranges") [fraction]
  double min_overlap = 0.5;
  /// Below this ratio of the weakest to the strongest eigenvalue of the scaled Hessian, a
  /// registration is degenerate [ratio]
  double min_constraint_ratio = 1e-3;
  /// Above this multiple of the predicted mean matched score (3 for the Mahalanobis score), a
  /// registration is suspect: the bar lies between the fits of right poses and of poses that slid or
  /// stuck (docs/matcher_defaults.md, "The thresholds' measured ranges") [ratio]
  double max_fit_ratio = 1.3;
  /// Two solutions that pass the checks and lie farther apart than this make a result ambiguous: at
  /// least one of them is off by half of it, the size of error the trust status exists to catch
  /// (issue 22: no step 1 m or 5° off is trusted) [m, °]
  double ambiguity_metres = 1.0;
  double ambiguity_degrees = 5.0;
  /// ... and that fits within this factor of the result: an alternative whose matched points fit
  /// clearly worse is told apart by the scans (docs/matcher_defaults.md, "The thresholds' measured
  /// ranges") [ratio ≥ 1]
  double ambiguity_fit_band = 1.1;
  bool valid(std::string* why) const;
};

/// Rotations scaled to metres at `rms_range`: S·H·S with S = diag(1, 1, 1, 1/L, 1/L, 1/L); its weakest
/// eigenvalue over its strongest, over the `free` parameters (a DOF mask's fixed ones are left out; a
/// free one whose row is zero is constrained by nothing: 0). A negative definite H, of a maximised
/// score, counts as −H. 0 for a non-finite or indefinite H; NaN for an all-zero H (a matcher that gives
/// none, such as PCL's: no degeneracy check).
double constraint_ratio(const Matrix6d& H, double rms_range, const DofMask& free = DofMask{});

/// RMS distance of the points from the origin of their frame (the sensor) [m]; 1 for an empty cloud.
double rms_range(const PointCloud& cloud);

/// The assessment of `result`, a registration of `input` (the points that were matched, already
/// sampled), from its overlap, Hessian and fit (result.mean_matched_score against
/// result.predicted_matched_score; no fit check when the matcher predicts nothing), and, when those
/// pass, from its alternatives.
RegistrationQuality assess_registration(const RegistrationResult& result, const PointCloud& input,
                                        const QualitySettings& settings = {});

/// Whether `a` and `b` lie farther apart than the settings' ambiguity tolerance (either part).
bool far_apart(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const QualitySettings& settings);

/// Whether a solution at `other` that passes the checks and fits `other_fit` × the prediction is a
/// rival of one at `pose` fitting `fit`: farther apart than the ambiguity tolerance, and fitting about
/// as well or better (within ambiguity_fit_band × `fit`). Two rivals cannot both be right, and the
/// scans cannot tell which is.
bool rivals(const Eigen::Isometry3d& pose, double fit, const Eigen::Isometry3d& other, double other_fit,
            const QualitySettings& settings);

}  // namespace sextant
