#pragma once
// Which registration a step chains when none is trusted (issue 22). The candidates are the step's
// registrations whose only flaw is their fit: converged, enough overlap, every direction
// constrained, matched points scoring above what a right pose predicts. Their fits say little
// more: along a straight road they lie close together, and the lowest can be the farthest off
// (docs/matcher_defaults.md, "Which registration a step chains when none is trusted"). So the scans
// pick a band — the fits within `fit_band` × the lowest, the sequence check's own tolerance for "fits
// about equally" (sequence_trust.hpp) — and the motion prior picks inside it: the candidate whose
// alignment of the input differs least from the guess's.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

struct SuspectCandidate {
  Eigen::Isometry3d relative = Eigen::Isometry3d::Identity();  ///< p_reference = relative · p_input
  double fit_ratio = 0.0;  ///< matched points' score over what a right pose predicts [ratio]
};

/// RMS distance between `input`'s points placed by `a` and by `b` (at most `max_points` of them,
/// evenly strided) [m]: how differently two poses align one scan, translation and rotation in one
/// unit. 0 for an empty cloud.
double alignment_distance(const PointCloud& input, const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                          std::size_t max_points = 2000);

/// The index of the candidate to chain: among those whose fit is within `fit_band` × the lowest
/// (fit_band ≥ 1), the one whose alignment of `input` is nearest the guess's; ties go to the lower
/// fit, then the earlier candidate. Requires a non-empty `candidates`.
std::size_t choose_suspect(const std::vector<SuspectCandidate>& candidates, const PointCloud& input,
                           const Eigen::Isometry3d& guess, double fit_band);

}  // namespace sextant
